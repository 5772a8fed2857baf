#include "accelcal/report/limited_by_text.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <fmt/core.h>

namespace accelcal {
namespace {

// The family of a parameter in words: "offsets", "scales", "misalignments".
std::string FamilyOf(int index) {
  if (index < 3) return "offset";
  if (index < 6) return "scale";
  return "misalignment";
}

// The budget's quantity in the certificate's words.
std::string SourceWords(const BudgetContribution& c, const Calibration& cal) {
  if (c.type == 'A')
    return cal.fit.scatter ? "the scatter between the captures beyond their noise (type A)"
                           : "the captures' noise (type A)";
  return "the " + c.quantity + " (type B)";
}

// "a", "a and b", "a, b and c".
std::string JoinWords(const std::vector<std::string>& parts) {
  std::string out;
  for (size_t i = 0; i < parts.size(); ++i)
    out += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
  return out;
}

}  // namespace

std::string LimitedByStatement(const Calibration& cal) {
  std::string out;
  if (cal.budget && !cal.budget->parameters.empty()) {
    // Each source and the parameters it dominates, by family, in the nine's order.
    struct Dominated {
      std::string source;
      std::vector<std::pair<std::string, std::vector<std::string>>> families;
    };
    std::vector<Dominated> sources;
    for (const ParameterBudget& p : cal.budget->parameters) {
      const BudgetContribution* largest = nullptr;
      for (const BudgetContribution& c : p.contributions)
        if (std::isfinite(c.contribution) &&
            (largest == nullptr || std::abs(c.contribution) > std::abs(largest->contribution)))
          largest = &c;
      if (largest == nullptr) continue;
      const std::string source = SourceWords(*largest, cal);
      auto d = std::find_if(sources.begin(), sources.end(), [&](const Dominated& x) { return x.source == source; });
      if (d == sources.end()) d = sources.insert(sources.end(), Dominated{source, {}});
      const std::string family = FamilyOf(p.index);
      auto f = std::find_if(d->families.begin(), d->families.end(), [&](const auto& x) { return x.first == family; });
      if (f == d->families.end()) f = d->families.insert(d->families.end(), std::make_pair(family, std::vector<std::string>{}));
      f->second.push_back(p.name);
    }
    std::vector<std::string> parts;
    for (const Dominated& d : sources) {
      std::vector<std::string> families;
      for (const auto& [family, names] : d.families)
        families.push_back(fmt::format("{}{} ({})", family, names.size() > 1 ? "s" : "", JoinWords(names)));
      parts.push_back(parts.empty() ? fmt::format("The uncertainty of the {} is limited by {}", JoinWords(families), d.source)
                                    : fmt::format("that of the {} by {}", JoinWords(families), d.source));
    }
    out.clear();
    for (size_t i = 0; i < parts.size(); ++i) out += (i == 0 ? "" : "; ") + parts[i];
    out += ".";
  } else {
    out = cal.fit.scatter ? "The uncertainty is that of the fit alone, from the scatter between the captures "
                            "beyond their noise."
                          : "The uncertainty is that of the fit alone, from the captures' noise.";
  }
  if (cal.limited_by.empty()) return out + " Nothing limits the calibration beyond the captures' noise.";
  out += " Beyond the captures' noise, the calibration is";
  for (size_t i = 0; i < cal.limited_by.size(); ++i)
    out += (i == 0 ? " " : "; and ") + cal.limited_by[i].words;
  return out + ".";
}

}  // namespace accelcal
