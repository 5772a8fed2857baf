#include "accelcal/acquire/mavlink/mavlink_source.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "accelcal/acquire/source/spec_options.h"
#include "accelcal/acquire/source/wall_clock.h"
#include "accelcal/base/error.h"
#include "accelcal/base/gravity.h"
#include "accelcal/base/text_scan.h"

namespace accelcal {
namespace {

using namespace mavlink;
using source_detail::WallNowS;

constexpr double kCountsPerMps2 = 1000.0;         // counts of 0.001 m/s^2
constexpr double kAckWaitS = 1.5;       // for SET_MESSAGE_INTERVAL's COMMAND_ACK
constexpr double kChooseWaitS = 1.0;    // for a HIGHRES_IMU after another IMU message came
constexpr double kRebootStepS = 0.5;    // the vehicle's clock going back more than this: a reboot
constexpr size_t kMaxHeld = 20000;      // readings held while the message is chosen

const char* kMavlinkUsage = "mavlink:LINK[,imu=N][,rate=HZ][,msg=highres|scaled|raw][,sys=N][,comp=N]";

std::uint32_t ScaledImuOf(int imu) { return imu == 0 ? kScaledImu : imu == 1 ? kScaledImu2 : kScaledImu3; }

// Better first: float m/s^2 with temperature, then mG, then the sensor's raw units.
int Preference(std::uint32_t message) {
  return message == kHighresImu ? 0 : message == kRawImu ? 2 : 1;
}

long ParseWhole(const std::string& spec, const std::string& key, const std::string& value, long lo, long hi) {
  long v = 0;
  if (!detail::ParseLong(value, &v) || v < lo || v > hi)
    throw Error(fmt::format("source '{}': {}={} is not a whole number in {}..{}", spec, key, value, lo, hi));
  return v;
}

}  // namespace

std::string MavlinkSourceSpec::Describe() const {
  std::string text = fmt::format("mavlink:{},imu={}", DescribeLink(link), imu);
  if (rate_hz != 100.0) text += fmt::format(",rate={}", rate_hz);
  if (message) text += ",msg=" + std::string(*message == kHighresImu ? "highres" : *message == kRawImu ? "raw" : "scaled");
  if (system >= 0) text += fmt::format(",sys={}", system);
  if (component >= 0) text += fmt::format(",comp={}", component);
  return text;
}

MavlinkSourceSpec ParseMavlinkSpec(const std::string& spec) {
  const std::string body = spec.substr(std::string_view("mavlink:").size());
  if (body.empty()) throw Error(fmt::format("source '{}': expected {}", spec, kMavlinkUsage));
  const SpecParts parts = SplitSpecOptions(body);
  MavlinkSourceSpec s;
  s.link = ParseLinkSpec(parts.head, spec);
  for (const SpecOption& o : parts.options) {
    const std::string& key = o.key;
    const std::string& value = o.value;
    if (key == "imu") {
      s.imu = static_cast<int>(ParseWhole(spec, key, value, 0, 2));
    } else if (key == "rate") {
      double hz = kNaN;
      if (!detail::ParseDouble(value, &hz) || !(hz >= 0.0) || hz > 10000.0)
        throw Error(fmt::format("source '{}': rate={} is not a rate in 0..10000 Hz (0: ask nothing)", spec, value));
      s.rate_hz = hz;
    } else if (key == "msg") {
      if (value == "highres") s.message = kHighresImu;
      else if (value == "scaled") s.message = kScaledImu;  // the imu's SCALED_IMU*, fixed below
      else if (value == "raw") s.message = kRawImu;
      else throw Error(fmt::format("source '{}': msg={}: expected highres, scaled or raw", spec, value));
    } else if (key == "sys") {
      s.system = static_cast<int>(ParseWhole(spec, key, value, 1, 255));
    } else if (key == "comp") {
      s.component = static_cast<int>(ParseWhole(spec, key, value, 0, 255));
    } else {
      throw Error(fmt::format("source '{}': unknown option '{}': expected {}", spec, o.text, kMavlinkUsage));
    }
  }
  if (s.message == kScaledImu) s.message = ScaledImuOf(s.imu);
  return s;
}

MavlinkSource::MavlinkSource(MavlinkSourceSpec spec, const SourceOptions& options)
    : spec_(std::move(spec)),
      connection_(spec_.link, [&] {
        ConnectionOptions c;
        c.system = spec_.system;
        c.component = spec_.component;
        c.reconnect_initial_s = options.reconnect_initial_s;
        c.reconnect_max_s = options.reconnect_max_s;
        return c;
      }()),
      tracker_(options.gap_factor, options.dead_after_s, WallNowS()) {
  connection_.SetObserver(this);
}

MavlinkSource::~MavlinkSource() { connection_.SetObserver(nullptr); }

ReadResult MavlinkSource::Read(double timeout_s, std::vector<Sample>* out) {
  ReadResult result;
  current_ = &result;
  const double deadline_s = WallNowS() + std::max(0.0, timeout_s);
  for (;;) {
    const double now_s = WallNowS();
    AdvanceRequest(now_s);
    ChooseIfDue(now_s);
    if (!ready_.empty() || now_s >= deadline_s) break;
    // Wake at least every 100 ms to run the request and the choice on time.
    connection_.Pump(std::min(deadline_s - now_s, 0.1), [&] { return !ready_.empty(); });
  }
  if (!ready_.empty()) {
    out->insert(out->end(), ready_.begin(), ready_.end());
    tracker_.OnSamples(ready_.data(), static_cast<long>(ready_.size()), WallNowS(), &result);
    ready_.clear();
  }
  tracker_.SetLostFrames(connection_.lost_frames());
  tracker_.Tick(WallNowS(), &result, Silence());
  // The heartbeats stopping is news even when the samples stopped first and the link is already
  // dead for want of them ("heartbeats arrive, but no HIGHRES_IMU" was its reason then): said
  // once per disappearance, and the dead link's reason becomes it.
  const bool gone = connection_.VehicleGone();
  if (gone && !vehicle_gone_said_ && !result.went_dead) tracker_.OnSilenceReason(Silence(), WallNowS(), &result);
  vehicle_gone_said_ = gone;
  current_ = nullptr;
  return result;
}

void MavlinkSource::Notice(const std::string& text, SourceNoticeKind kind) {
  tracker_.OnNotice(text, &Events(), kind);
}

void MavlinkSource::OnLinkUp() { tracker_.OnLinkUp(WallNowS(), &Events()); }

void MavlinkSource::OnLinkLost(const std::string& why) {
  tracker_.OnLinkLost(why, &Events());
  request_ = Request::kNotYet;  // a vehicle that comes back is asked again
}

void MavlinkSource::OnOpenFailed(const std::string& why) { tracker_.OnOpenFailed(why); }

void MavlinkSource::OnBadFrames(long count, const std::string& latest) {
  tracker_.OnMalformed(count, fmt::format("{}: {}", connection_.LinkName(), latest), &Events());
}

void MavlinkSource::OnFrame(const Frame& frame, bool from_vehicle) {
  // Before any heartbeat, IMU messages from whoever sends them (a bare IMU board sends none).
  const bool accept = from_vehicle || !connection_.vehicle().known;
  if (!accept) return;
  if (frame.message == kHeartbeat && from_vehicle) {
    // Heard again after a silence (a reboot on a link that stayed up): ask for the rate again.
    const double now_s = WallNowS();
    if (request_ == Request::kDone && now_s - last_heartbeat_s_ > 3.0) request_ = Request::kNotYet;
    last_heartbeat_s_ = now_s;
  }
  if (frame.message == kCommandAck && request_ == Request::kAwaitAck) {
    const CommandAck ack = DecodeCommandAck(frame.payload);
    if (ack.command != kCmdSetMessageInterval) return;
    if (ack.result == 0) {
      request_ = Request::kDone;
      request_done_s_ = WallNowS();
      request_outcome_ = fmt::format("asked {} at {:g} Hz with SET_MESSAGE_INTERVAL: accepted",
                                     MessageName(WantedMessage()), spec_.rate_hz);
    } else {
      FallBackToDataStream(fmt::format("SET_MESSAGE_INTERVAL {}", CommandResultText(ack.result)));
    }
    return;
  }
  if (const std::optional<ImuReading> reading = DecodeImu(frame.message, frame.payload)) OnImu(*reading);
}

std::uint32_t MavlinkSource::WantedMessage() const {
  return spec_.message ? *spec_.message : kHighresImu;
}

void MavlinkSource::AdvanceRequest(double now_s) {
  if (spec_.rate_hz <= 0.0 || !connection_.open()) return;
  if (request_ == Request::kNotYet && connection_.vehicle().known) SendRateRequest();
  if (request_ == Request::kAwaitAck && now_s >= ack_deadline_s_)
    FallBackToDataStream("SET_MESSAGE_INTERVAL not answered");
}

void MavlinkSource::SendRateRequest() {
  const std::array<float, 7> params = {static_cast<float>(WantedMessage()),
                                       static_cast<float>(1e6 / spec_.rate_hz), 0, 0, 0, 0, 0};
  connection_.Send(kCommandLong, EncodeCommandLong(connection_.target_system(), connection_.target_component(),
                                                   kCmdSetMessageInterval, params));
  request_ = Request::kAwaitAck;
  ack_deadline_s_ = WallNowS() + kAckWaitS;
}

void MavlinkSource::FallBackToDataStream(const std::string& why) {
  const auto rate = static_cast<std::uint16_t>(std::clamp(std::lround(spec_.rate_hz), 1L, 65535L));
  connection_.Send(kRequestDataStream, EncodeRequestDataStream(connection_.target_system(),
                                                               connection_.target_component(),
                                                               kDataStreamRawSensors, rate, true));
  request_ = Request::kDone;
  request_done_s_ = WallNowS();
  request_outcome_ = fmt::format("{} (asked {} at {:g} Hz): asked the raw-sensor stream at {} Hz "
                                 "with REQUEST_DATA_STREAM instead (older firmware's way; it is "
                                 "never acknowledged)",
                                 why, MessageName(WantedMessage()), spec_.rate_hz, rate);
  Notice(fmt::format("{}: {}", connection_.LinkName(), request_outcome_), SourceNoticeKind::kRateRequest);
}

void MavlinkSource::OnImu(const ImuReading& reading) {
  ++streams_[{reading.message, reading.instance}];
  if (reading.instance != spec_.imu) return;
  if (chosen_) {
    if (reading.message == *chosen_) Emit(reading);
    return;
  }
  if (spec_.message) {
    if (reading.message == *spec_.message) {
      Choose(reading.message);
      Emit(reading);
    }
    return;
  }
  if (reading.message == kHighresImu) {
    Choose(kHighresImu);
    Emit(reading);
    return;
  }
  if (first_other_s_ < 0.0) first_other_s_ = WallNowS();
  std::vector<ImuReading>& held = held_[reading.message];
  if (held.size() < kMaxHeld) held.push_back(reading);
}

// Without a HIGHRES_IMU: the best of what came, once it had time to come (and the rate request
// was answered or given up).
void MavlinkSource::ChooseIfDue(double now_s) {
  if (chosen_ || held_.empty() || first_other_s_ < 0.0) return;
  const bool request_settled =
      spec_.rate_hz <= 0.0 || (request_ == Request::kDone && now_s >= request_done_s_ + 0.5);
  // Never wait long on a request nobody answers.
  const bool due = (now_s >= first_other_s_ + kChooseWaitS && request_settled) ||
                   now_s >= first_other_s_ + 3.0 * kChooseWaitS;
  if (!due) return;
  std::uint32_t best = held_.begin()->first;
  for (const auto& [message, readings] : held_)
    if (Preference(message) < Preference(best)) best = message;
  Choose(best);
  Notice(fmt::format("{}: no HIGHRES_IMU of IMU {} came; reading {} instead", connection_.LinkName(),
                     spec_.imu, MessageName(best)),
         SourceNoticeKind::kCoarserReadings);
  const std::vector<ImuReading> held = std::move(held_[best]);
  held_.clear();
  for (const ImuReading& r : held) Emit(r);
}

void MavlinkSource::Choose(std::uint32_t message) {
  chosen_ = message;
  held_.clear();
  if (message == kRawImu) {
    tracker_.SetUnit(ReadingUnit{}, 1.0);
  } else {
    const ReadingUnit unit{ReadingUnit::Kind::kMps2, kCountsPerMps2};
    tracker_.SetUnit(unit, message == kHighresImu ? kNaN : kStandardGravityMps2);  // 1 mG in counts
  }
}

void MavlinkSource::Emit(const ImuReading& reading) {
  Sample s;
  Eigen::Vector3d acc(reading.acc[0], reading.acc[1], reading.acc[2]);
  if (reading.message != kRawImu) {
    if (reading.message != kHighresImu) acc *= kStandardGravityMps2 / 1000.0;  // mG -> m/s^2
    if (undo_) acc = undo_->SensorFromSent(acc);
    acc *= kCountsPerMps2;
  }
  s.raw_counts = acc;
  s.temp_c = reading.temp_c;
  const double now_wall_s = WallNowS();
  if (!std::isnan(last_vehicle_t_s_) && reading.time_s < last_vehicle_t_s_ - kRebootStepS) {
    const double gap_s = std::max(now_wall_s - last_sample_wall_s_, 0.01);
    offset_s_ = last_t_s_ + gap_s - reading.time_s;
    ++reboots_;
    Notice(fmt::format("{}: {} rebooted (its clock went back from {:.3f} s to {:.3f} s): the samples "
                       "go on after a gap of {:.1f} s",
                       connection_.LinkName(), connection_.vehicle().Describe(), last_vehicle_t_s_,
                       reading.time_s, gap_s),
           SourceNoticeKind::kRestarted);
  }
  s.t_s = reading.time_s + offset_s_;
  if (!std::isnan(last_t_s_) && s.t_s <= last_t_s_) {
    if (reading.time_s == last_vehicle_t_s_) {
      // Same stamp twice (SCALED_IMU's milliseconds at a high rate): spread by a microsecond.
      s.t_s = last_t_s_ + 1e-6;
      ++ties_spread_;
    } else {
      tracker_.OnMalformed(1, fmt::format("{}: {} time went back from {:.6f} s to {:.6f} s: dropped",
                                          connection_.LinkName(), MessageName(reading.message),
                                          last_vehicle_t_s_, reading.time_s),
                           &Events());
      return;
    }
  }
  last_vehicle_t_s_ = reading.time_s;
  last_t_s_ = s.t_s;
  last_sample_wall_s_ = now_wall_s;
  ready_.push_back(s);
}

std::string MavlinkSource::Silence() const {
  if (!connection_.open()) return connection_.link_error();
  const VehicleIdentity& v = connection_.vehicle();
  const double age_s = connection_.HeartbeatAgeS();
  if (!v.known) return fmt::format("no vehicle's heartbeat heard on {}", connection_.LinkName());
  if (connection_.VehicleGone())
    return fmt::format("no heartbeat from {} for {:.1f} s: the vehicle is gone (powered off, "
                       "rebooting, or the link lost)", v.Describe(), age_s);
  return fmt::format("heartbeats from {} arrive, but no {} of IMU {}", v.Describe(),
                     spec_.message ? MessageName(*spec_.message) : "HIGHRES_IMU, SCALED_IMU or RAW_IMU",
                     spec_.imu);
}

std::string MavlinkSource::DescribeReading() const {
  std::string text;
  if (chosen_) {
    text = fmt::format("{} of IMU {} from {}: {}", MessageName(*chosen_), spec_.imu,
                       connection_.vehicle().Describe(), status().unit.Describe());
    text += *chosen_ == kHighresImu ? " (resolution: float)"
            : *chosen_ == kRawImu   ? " (resolution: 1 count)"
                                    : " (resolution: 1 mG = 9.80665 counts)";
  } else {
    text = fmt::format("no IMU message of IMU {} yet from {}", spec_.imu, connection_.vehicle().Describe());
  }
  if (!request_outcome_.empty()) text += "; rate: " + request_outcome_;
  else if (spec_.rate_hz <= 0.0) text += "; rate: not asked (rate=0)";
  const FrameCounters& c = connection_.counters();
  text += fmt::format("; {} frames, {} lost, {} bad CRC, {} wrong length, {} garbage bytes, {} of "
                      "other messages skipped",
                      c.frames, connection_.lost_frames(), c.bad_crc, c.wrong_length,
                      c.garbage_bytes, c.other_messages);
  if (c.other_messages > 0) text += fmt::format(" (latest: {})", MessageName(c.last_other_message));
  if (c.signed_frames > 0) text += fmt::format(", {} signed (signatures not checked)", c.signed_frames);
  if (c.v1_frames > 0) text += fmt::format(", {} MAVLink 1", c.v1_frames);
  if (ties_spread_ > 0) text += fmt::format("; {} repeated time stamps spread by 1 us", ties_spread_);
  if (reboots_ > 0) text += fmt::format("; the vehicle rebooted {} time{}", reboots_, reboots_ == 1 ? "" : "s");
  text += undo_ ? "; the vehicle's own calibration undone: " + undo_->description
                : "; the vehicle's own calibration: left in the readings";
  return text;
}

}  // namespace accelcal
