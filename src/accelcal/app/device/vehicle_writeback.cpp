#include "accelcal/app/device/vehicle_writeback.h"

#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "accelcal/base/error.h"
#include "accelcal/base/gravity.h"
#include "accelcal/io/export/ardupilot_params.h"
#include "accelcal/io/export/px4_params.h"

namespace accelcal {
namespace {


std::string TypeName(std::uint8_t type) {
  switch (type) {
    case mavlink::kParamTypeReal32: return "REAL32";
    case mavlink::kParamTypeInt32: return "INT32";
    case mavlink::kParamTypeInt8: return "INT8";
    case mavlink::kParamTypeInt16: return "INT16";
  }
  return fmt::format("type {}", type);
}

// What the vehicle holds, as the number it means, against what was sent (both through float32:
// the parameters are 32-bit).
bool SameValue(const mavlink::ParamValue& held, const ParamWrite& w, bool bytewise) {
  const float sent = mavlink::ParamWireFloat(w.value, w.type, bytewise);
  mavlink::ParamValue as_sent = held;
  as_sent.value = sent;
  return mavlink::ParamNumber(held, bytewise) == mavlink::ParamNumber(as_sent, bytewise);
}

std::string Shown(const mavlink::ParamValue& v, bool bytewise) {
  return fmt::format("{:.9g}", mavlink::ParamNumber(v, bytewise));
}

std::string ReplaceAll(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

std::string ForImu(const std::string& line, FlightStack stack, int imu) {
  if (imu == 0) return line;
  if (stack == FlightStack::kPx4) return ReplaceAll(line, "CAL_ACC0_", fmt::format("CAL_ACC{}_", imu));
  return ReplaceAll(ReplaceAll(line, "INS_ACCOFFS_", fmt::format("INS_ACC{}OFFS_", imu + 1)), "INS_ACCSCAL_",
                    fmt::format("INS_ACC{}SCAL_", imu + 1));
}

}  // namespace

std::optional<DriverScaleOptions> DriverScaleOfUnit(const ReadingUnit& unit) {
  if (unit.is_counts()) return std::nullopt;
  DriverScaleOptions d;
  const double per_mps2 = unit.kind == ReadingUnit::Kind::kMps2 ? unit.counts_per_unit
                                                                : unit.counts_per_unit / kStandardGravityMps2;
  d.nominal_scale_counts_per_mps2 = Eigen::Vector3d::Constant(per_mps2);
  d.nominal_bias_counts = Eigen::Vector3d::Zero();
  return d;
}

WritebackPlan PlanWriteback(const Calibration& cal, FlightStack stack, int imu, const DriverScaleOptions& driver) {
  WritebackPlan plan;
  plan.stack = stack;
  plan.imu = imu;
  const AccelParamNames names = AccelParamNamesFor(stack, imu);
  const DiagonalCorrection c = ToDiagonalCorrection(cal, driver);
  for (size_t j = 0; j < 3; ++j)
    plan.writes.push_back({names.offset[j], c.offset_mps2(static_cast<Eigen::Index>(j)), mavlink::kParamTypeReal32});
  for (size_t j = 0; j < 3; ++j)
    plan.writes.push_back({names.scale[j], c.scale(static_cast<Eigen::Index>(j)), mavlink::kParamTypeReal32});
  // The statements of the file export for the same target, word for word.
  const ExportResult words = stack == FlightStack::kArduPilot
                                 ? ExportArduPilotParams(cal, driver, {})
                                 : ExportPx4Params(cal, {driver, std::nullopt}, {});
  plan.cannot_hold = words.cannot_hold;
  for (const std::string& note : words.notes)
    if (note.find("INS_ACC_ID is not written") == std::string::npos) plan.notes.push_back(note);
  // The device id: on the vehicle already, and left as it is.
  std::erase_if(plan.cannot_hold, [](const std::string& s) { return s.rfind("CAL_ACC0_ID", 0) == 0; });
  // The export's words name IMU 0's parameters; these writes are this IMU's.
  for (std::vector<std::string>* lines : {&plan.cannot_hold, &plan.notes})
    for (std::string& line : *lines) line = ForImu(line, stack, imu);
  plan.notes.push_back(fmt::format("{} is left as the vehicle has it: it names the sensor these values belong to",
                                   names.device_id));
  return plan;
}

std::vector<std::string> DescribeWrites(const std::vector<ParamWrite>& writes) {
  std::vector<std::string> lines;
  for (const ParamWrite& w : writes)
    lines.push_back(fmt::format("PARAM_SET {} = {:.9g} ({})", w.name, w.value, TypeName(w.type)));
  return lines;
}

std::vector<std::string> WritebackOutcome::Lines() const {
  std::vector<std::string> lines;
  if (!before.empty()) {
    std::vector<std::string> shown;
    for (const auto& [name, value] : before) shown.push_back(fmt::format("{} = {:.9g}", name, value));
    lines.push_back(fmt::format("before: {}", fmt::join(shown, ", ")));
  }
  lines.push_back(written.empty() ? "written: none" : fmt::format("written: {}", fmt::join(written, ", ")));
  if (!failed.empty()) lines.push_back("stopped: " + failed);
  if (!not_sent.empty()) lines.push_back(fmt::format("not written: {}", fmt::join(not_sent, ", ")));
  for (const std::string& m : reread_mismatches) lines.push_back("read back: " + m);
  if (ok()) lines.push_back(fmt::format("read back: all {} as written", written.size()));
  return lines;
}

WritebackOutcome ApplyWrites(mavlink::Connection& link, FlightStack stack, const std::vector<ParamWrite>& writes,
                             const mavlink::ParamExchange& exchange) {
  const bool bytewise = stack == FlightStack::kPx4;
  WritebackOutcome out;
  std::vector<std::string> names;
  for (const ParamWrite& w : writes) names.push_back(w.name);
  const mavlink::ParamReadResult first = mavlink::ReadParams(link, names, exchange);
  for (const auto& [name, v] : first.values) out.before[name] = mavlink::ParamNumber(v, bytewise);
  if (!first.unanswered.empty()) {
    out.failed = fmt::format("{}: the vehicle ({}) answered no PARAM_REQUEST_READ for {} in {} tries of "
                             "{:.1f} s: nothing was written",
                             link.LinkName(), link.vehicle().Describe(), fmt::join(first.unanswered, ", "),
                             exchange.rounds, exchange.round_s);
    out.not_sent = names;
    return out;
  }
  for (size_t i = 0; i < writes.size(); ++i) {
    const ParamWrite& w = writes[i];
    const float wire = mavlink::ParamWireFloat(w.value, w.type, bytewise);
    const std::optional<mavlink::ParamValue> echo = mavlink::SetParam(link, w.name, wire, w.type, exchange);
    std::string problem;
    if (!echo)
      problem = fmt::format("{}: no PARAM_VALUE echoed the PARAM_SET of {} = {:.9g} in {} tries of {:.1f} s "
                            "(it may or may not hold the new value)",
                            link.LinkName(), w.name, w.value, exchange.rounds, exchange.round_s);
    else if (!SameValue(*echo, w, bytewise))
      problem = fmt::format("{}: {} was set to {:.9g} but the vehicle echoed {}: it holds that, not the calibration",
                            link.LinkName(), w.name, w.value, Shown(*echo, bytewise));
    if (!problem.empty()) {
      out.failed = problem;
      for (size_t k = i + 1; k < writes.size(); ++k) out.not_sent.push_back(writes[k].name);
      return out;
    }
    out.written.push_back(w.name);
  }
  const mavlink::ParamReadResult back = mavlink::ReadParams(link, names, exchange);
  for (const ParamWrite& w : writes) {
    const auto it = back.values.find(w.name);
    if (it == back.values.end())
      out.reread_mismatches.push_back(fmt::format("{}: not answered", w.name));
    else if (!SameValue(it->second, w, bytewise))
      out.reread_mismatches.push_back(fmt::format("{} holds {}, not {:.9g}", w.name, Shown(it->second, bytewise), w.value));
  }
  return out;
}

}  // namespace accelcal
