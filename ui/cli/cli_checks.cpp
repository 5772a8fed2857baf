#include "cli/cli_checks.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal::cli {
namespace {

// `text` as a finite number, or NaN.
double AsNumber(const std::string& text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    return std::nan("");
  return value;
}

}  // namespace

CLI::Validator NonNegative() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const double v = AsNumber(text);
        if (std::isnan(v)) return fmt::format("'{}' is not a number", text);
        return v < 0.0 ? fmt::format("must be 0 or more, not {}", text) : "";
      },
      "NUMBER >= 0", "NonNegative");
}

CLI::Validator Positive() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const double v = AsNumber(text);
        if (std::isnan(v)) return fmt::format("'{}' is not a number", text);
        return v <= 0.0 ? fmt::format("must be more than 0, not {}", text) : "";
      },
      "NUMBER > 0", "Positive");
}

CLI::Validator InputFile() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) throw Error(fmt::format("no such file: {}", path));
        if (std::filesystem::is_directory(path, ec))
          throw Error(fmt::format("{} is a directory, not a file", path));
        return "";
      },
      "FILE", "InputFile");
}

CLI::Validator InputFileOrBag() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) throw Error(fmt::format("no such file: {}", path));
        if (std::filesystem::is_directory(path, ec) &&
            !std::filesystem::exists(std::filesystem::path(path) / "metadata.yaml", ec))
          throw Error(fmt::format("{} is a directory, not a file (nor a ROS 2 bag folder: it "
                                  "holds no metadata.yaml)", path));
        return "";
      },
      "FILE|BAG", "InputFileOrBag");
}

std::vector<std::string> SplitAt(std::string_view text, char separator) {
  std::vector<std::string> pieces;
  size_t from = 0;
  while (from <= text.size()) {
    const size_t end = std::min(text.find(separator, from), text.size());
    if (end > from) pieces.emplace_back(text.substr(from, end - from));
    from = end + 1;
  }
  return pieces;
}

std::vector<std::string> OptionChoices(const CLI::Option& option) {
  const std::string type = option.get_type_name();
  const size_t open = type.find('{');
  const size_t close = type.find('}', open);
  if (open == std::string::npos || close == std::string::npos) return {};
  return SplitAt(std::string_view(type).substr(open + 1, close - open - 1), ',');
}

void RefuseNegativeWholeNumbers(CLI::App& app) {
  const CLI::Validator whole(
      [](std::string& text) -> std::string {
        return text.find('-') == std::string::npos
                   ? ""
                   : fmt::format("must be a whole number, 0 or more, not {}", text);
      },
      "", "WholeNumber");
  for (CLI::Option* opt : app.get_options()) {
    const std::string type = opt->get_type_name();
    if (type.substr(0, type.find(':')) == "UINT") opt->check(whole);
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) RefuseNegativeWholeNumbers(*sub);
}

}  // namespace accelcal::cli
