// mavlink:<link>[,imu=N][,rate=HZ][,msg=highres|scaled|raw][,sys=N][,comp=N]: the accelerometer of
// a flight controller (ArduPilot, PX4) as a sample source. <link> as in mavlink_link.h.
//
// The stream: HIGHRES_IMU (float m/s^2, temperature) is preferred; SCALED_IMU, SCALED_IMU2 and
// SCALED_IMU3 (int16 mG: IMU 0, 1, 2) or RAW_IMU (the sensor's own units) otherwise; `msg=`
// forces one. The IMU is `imu=` (the id field of HIGHRES_IMU and RAW_IMU; which SCALED_IMU*
// message). When a HIGHRES_IMU does not come within about a second of the others, the best
// that came is taken and said.
//
// Counts: the model is in counts; HIGHRES_IMU and SCALED_IMU readings are m/s^2 (mG converted
// exactly, 1 mG = 9.80665e-3 m/s^2), taken as counts of 0.001 m/s^2 (sample_format.h's
// ReadingUnit); RAW_IMU's are counts as they come. The status says which, and the resolution: a
// SCALED_IMU stream moves in steps of 1 mG = 9.80665 counts, so a quiet sensor's noise is hidden
// in the rounding (std below 2.8 counts is the rounding's).
//
// The rate: asked once the vehicle is heard (rate=, default 100 Hz; rate=0 asks nothing) with
// MAV_CMD_SET_MESSAGE_INTERVAL, or REQUEST_DATA_STREAM (the raw-sensor group) when the vehicle
// refuses or does not answer; what it sends is measured (status().rate_hz) and the request's
// outcome said (DescribeReading).
//
// Time: the message's own time stamp (time_usec, or time_boot_ms for SCALED_IMU*). A vehicle that
// reboots starts its clock again: the samples go on after the last one by the wall-clock gap, and
// the reboot is a notice. Frames the vehicle numbered but that never came are counted as lost
// (status().lost_frames); a gap in t is a gap as for every source.
//
// The vehicle's own calibration: its readings arrive already corrected (offsets, scales, board
// rotation). SetUndo takes that correction back from every sample of an IMU instance
// (accel_undo.h); the app reads the vehicle's parameters to build it, per instance
// (app/device/vehicle_session.h).
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "accelcal/acquire/mavlink/accel_undo.h"
#include "accelcal/acquire/mavlink/mavlink_connection.h"
#include "accelcal/acquire/source/sample_source.h"
#include "accelcal/acquire/source/sensor_set_source.h"
#include "accelcal/acquire/source/source_options.h"
#include "accelcal/acquire/source/status_tracker.h"

namespace accelcal {

struct MavlinkSourceSpec {
  mavlink::LinkSpec link;
  int imu = 0;                // 0..2
  double rate_hz = 100.0;     // asked; 0: ask nothing
  std::optional<std::uint32_t> message;  // forced: kHighresImu, kScaledImu (the imu's), kRawImu
  int system = -1, component = -1;

  // "mavlink:tcp:127.0.0.1:5760,imu=0,rate=100".
  std::string Describe() const;
};

// Throws accelcal::Error naming the spec for anything malformed.
MavlinkSourceSpec ParseMavlinkSpec(const std::string& spec);

class MavlinkSource final : public SampleSource, private mavlink::ConnectionObserver {
 public:
  // Reads options' dead_after_s, gap_factor and reconnect_*. Opens nothing yet. `imus`: the IMU
  // instances read from the one connection, each its own stream with its own status (a vehicle
  // with three IMUs: {0, 1, 2}; mavlink_sensor_set.h); empty: the spec's imu= alone. Read() and
  // status() are the first instance's.
  MavlinkSource(MavlinkSourceSpec spec, const SourceOptions& options, std::vector<int> imus = {});
  ~MavlinkSource() override;

  std::string Describe() const override { return spec_.Describe(); }
  ReadResult Read(double timeout_s, std::vector<Sample>* out) override;
  const SourceStatus& status() const override { return lanes_.front().tracker.status(); }
  // "HIGHRES_IMU of IMU 0 from system 1 component 1 (ArduPilot): m/s^2, taken as counts of
  // 0.001 m/s^2 (resolution: float); rate: asked 100 Hz with SET_MESSAGE_INTERVAL, accepted; ...".
  std::string DescribeReading() const override { return DescribeReading(0); }

  // Every instance at once: out->per_sensor[i] gets instance imus[i]'s samples (resized first);
  // returns as soon as one instance has samples, or at the timeout. The result merges theirs.
  ReadResult ReadAll(double timeout_s, std::vector<std::vector<Sample>>* out);
  std::size_t imu_count() const { return lanes_.size(); }
  int imu(std::size_t lane) const { return lanes_.at(lane).imu; }
  const SourceStatus& status(std::size_t lane) const { return lanes_.at(lane).tracker.status(); }
  std::string DescribeReading(std::size_t lane) const;

  const MavlinkSourceSpec& spec() const { return spec_; }
  // The link, for a parameter exchange in the middle of the stream (samples keep coming in).
  mavlink::Connection& connection() { return connection_; }
  // Takes the vehicle's correction of IMU instance imu(lane) back from every later sample of that
  // instance (nullopt: as sent); each instance has its own (its own INS_ACCnOFFS ...). Applies
  // to HIGHRES_IMU and SCALED_IMU streams; RAW_IMU is the sensor's units already.
  void SetUndo(std::size_t lane, std::optional<mavlink::AccelUndo> undo) { lanes_.at(lane).undo = std::move(undo); }
  const std::optional<mavlink::AccelUndo>& undo(std::size_t lane = 0) const { return lanes_.at(lane).undo; }
  // The first instance's chosen message (nullopt until chosen).
  std::optional<std::uint32_t> message() const { return lanes_.front().chosen; }
  // Every (message, IMU instance) seen from the vehicle with its frame count.
  const std::map<std::pair<std::uint32_t, int>, long>& imu_streams() const { return streams_; }

 private:
  enum class Request { kNotYet, kAwaitAck, kDone };

  // One IMU instance's stream: its message (chosen or forced), its clock, its status.
  struct Lane {
    Lane(int imu_index, std::optional<std::uint32_t> forced_message, const SourceOptions& options,
         double now_s)
        : imu(imu_index), forced(forced_message), tracker(options.gap_factor, options.dead_after_s, now_s) {}
    int imu;
    std::optional<std::uint32_t> forced;  // msg=: kHighresImu, this instance's SCALED_IMU*, kRawImu
    StatusTracker tracker;
    ReadResult result;  // the events of the Read in progress (or since the last one)
    std::optional<mavlink::AccelUndo> undo;
    std::optional<std::uint32_t> chosen;
    double first_other_s = -1.0;  // wall time the first non-preferred IMU message came
    std::map<std::uint32_t, std::vector<mavlink::ImuReading>> held;  // while choosing
    std::vector<Sample> ready;
    double offset_s = 0.0;  // added to the vehicle's time stamps (reboots)
    double last_vehicle_t_s = kNaN;
    double last_t_s = kNaN;
    double last_sample_wall_s = kNaN;
    long ties_spread = 0;
    long reboots = 0;
    bool vehicle_gone_said = false;  // its heartbeats' stop was said (until they come again)
  };

  void OnFrame(const mavlink::Frame& frame, bool from_vehicle) override;
  void OnLinkUp() override;
  void OnLinkLost(const std::string& why) override;
  void OnOpenFailed(const std::string& why) override;
  void OnBadFrames(long count, const std::string& latest) override;

  bool AnyReady() const;
  void Deliver(Lane& lane, std::vector<Sample>* out);
  void Notice(Lane& lane, const std::string& text, SourceNoticeKind kind);
  void NoticeAll(const std::string& text, SourceNoticeKind kind);
  void OnImu(const mavlink::ImuReading& reading);
  void OnLaneImu(Lane& lane, const mavlink::ImuReading& reading);
  void AdvanceRequest(double now_s);
  void SendRateRequest();
  void OnRateAccepted();
  void FallBackToDataStream(const std::string& why);
  void ChooseIfDue(Lane& lane, double now_s);
  void Choose(Lane& lane, std::uint32_t message);
  void Emit(Lane& lane, const mavlink::ImuReading& reading);
  std::uint32_t WantedMessage(const Lane& lane) const;
  std::string WantedNames() const;
  std::string Silence(const Lane& lane) const;

  MavlinkSourceSpec spec_;
  mavlink::Connection connection_;
  std::vector<Lane> lanes_;  // at least one

  Request request_ = Request::kNotYet;
  std::vector<std::uint32_t> to_ask_;  // the messages whose rate is asked, one after the other
  std::size_t asked_ = 0;              // to_ask_[asked_] is the one asked now
  double ack_deadline_s_ = 0.0;
  double request_done_s_ = -1e300;
  double last_heartbeat_s_ = -1e300;  // wall time of the vehicle's latest heartbeat
  std::string request_outcome_;
  std::map<std::pair<std::uint32_t, int>, long> streams_;
};

}  // namespace accelcal
