#include "accelcal/report/bag_info_text.h"

#include <ctime>

#include <fmt/format.h>

#include "accelcal/base/duration_text.h"
#include "accelcal/base/text_scan.h"

namespace accelcal {
namespace {

// Seconds since 1970 as UTC ("2023-11-14 22:13:20.001 UTC"); a time before 2001 is a clock
// that does not count from 1970 (a robot's boot time): shown as seconds.
std::string BagTimeText(double t_s) {
  if (!(t_s > 978307200.0)) return fmt::format("{:.3f} s", t_s);
  const auto whole = static_cast<std::time_t>(t_s);
  std::tm tm{};
  gmtime_r(&whole, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", &tm);
  return fmt::format("{}.{:03d} UTC", text, static_cast<int>((t_s - static_cast<double>(whole)) * 1000.0));
}

std::string RateHz(const bags::TimeStats& s) {
  return s.median_interval_s > 0.0 ? fmt::format("{:.4g}", 1.0 / s.median_interval_s) : "-";
}

std::string GapsText(const bags::TimeStats& s) {
  if (s.gaps == 0) return "no gap";
  return fmt::format("{} gap{} (the largest {:.3g} s after {})", s.gaps, s.gaps == 1 ? "" : "s",
                     s.largest_gap_s, BagTimeText(s.largest_gap_at_s));
}

}  // namespace

std::string FormatBagInfo(const bags::BagInfo& info) {
  long long messages = 0;
  double first = 0.0, last = 0.0;
  bool any = false;
  for (const bags::TopicInfo& t : info.topics) {
    messages += t.receive.count;
    if (t.receive.count == 0) continue;
    if (!any || t.receive.first_s < first) first = t.receive.first_s;
    if (!any || t.receive.last_s > last) last = t.receive.last_s;
    any = true;
  }
  std::string out = fmt::format("{}: {}; {} topic{}, {} message{}\n", info.path, info.description,
                                info.topics.size(), info.topics.size() == 1 ? "" : "s", messages,
                                messages == 1 ? "" : "s");
  if (any)
    out += fmt::format("recorded {} to {} ({})\n", BagTimeText(first), BagTimeText(last),
                       FormatLongDuration(last - first));
  size_t name_width = 5, type_width = 4;
  for (const bags::TopicInfo& t : info.topics) {
    name_width = std::max(name_width, std::min<size_t>(t.name.size(), 40));
    type_width = std::max(type_width, std::min<size_t>(t.type.size(), 40));
  }
  out += fmt::format("\n  {:<{}}  {:<{}}  {:>9}  {:>9}  {:>11}  {}\n", "topic", name_width, "type",
                     type_width, "messages", "rate Hz", "span", "gaps (receive times)");
  for (const bags::TopicInfo& t : info.topics) {
    out += fmt::format("  {:<{}}  {:<{}}  {:>9}  {:>9}  {:>11}  {}\n",
                       detail::PrintableExcerpt(t.name, 40), name_width,
                       detail::PrintableExcerpt(t.type, 40), type_width, t.receive.count,
                       RateHz(t.receive), FormatLongDuration(t.receive.last_s - t.receive.first_s),
                       t.receive.count > 1 ? GapsText(t.receive) : "-");
  }
  bool any_imu = false;
  for (const bags::TopicInfo& t : info.topics) {
    if (!t.imu) continue;
    if (!any_imu)
      out += "\nIMU topics by their header stamps (what accelcal reads; a gap is over 1.5\n"
             "median intervals, as `accelcal allan` counts them):\n";
    any_imu = true;
    const bags::TimeStats& s = t.stamps;
    out += fmt::format("  {}: ", detail::PrintableExcerpt(t.name, 40));
    if (s.count == 0) {
      out += "no stamp read";
    } else {
      out += fmt::format("{} stamps, {} Hz, {}", s.count, RateHz(s), GapsText(s));
      out += s.out_of_order == 0 ? ", none out of order"
                                 : fmt::format(", {} out of order (or repeated): read with "
                                               "--bag-time receive, or repaired when rounded",
                                               s.out_of_order);
      if (s.count > 0 && s.first_s == 0.0 && s.last_s == 0.0)
        out += "; the stamps are zero: accelcal reads the receive times instead";
      else
        out += fmt::format("\n    {} to {} ({})", BagTimeText(s.first_s), BagTimeText(s.last_s),
                           FormatLongDuration(s.last_s - s.first_s));
    }
    if (t.undecodable > 0 || !t.undecodable_why.empty())
      out += fmt::format("; {} message{} not read: {}", t.undecodable, t.undecodable == 1 ? "" : "s",
                         t.undecodable_why);
    out += "\n";
  }
  if (!any_imu) out += "\nno sensor_msgs/Imu topic: nothing here for accelcal to read\n";
  for (const std::string& n : info.notes) out += fmt::format("note: {}\n", n);
  return out;
}

}  // namespace accelcal
