// One MAVLink link to one vehicle: opens and reopens the transport (with the text links'
// back-off), reads and checks frames (mavlink_frame.h), sends our heartbeat once a second
// (a ground station's: type GCS, system 255, component 190), picks the vehicle (the first
// autopilot heard, or the system/component asked) and watches its heartbeat, and counts the
// frames the vehicle's sequence numbers say were lost.
//
// Everything that arrives goes to one observer (the sample source, when there is one) and to
// the caller of Pump (a parameter exchange), so a parameter read in the middle of a stream loses
// no sample. Frames from other systems reach the observer too (a later multi-IMU source may
// want them); the vehicle's frames are marked.
//
// Units: times in s of wall clock (steady).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "accelcal/acquire/mavlink/mavlink_frame.h"
#include "accelcal/acquire/mavlink/mavlink_link.h"
#include "accelcal/acquire/source/reconnect_backoff.h"

namespace accelcal::mavlink {

struct ConnectionOptions {
  int system = -1;      // the vehicle's system id; -1: the first autopilot heard
  int component = -1;   // its component id; -1: the one whose heartbeat names an autopilot
  double heartbeat_period_s = 1.0;   // ours
  double heartbeat_timeout_s = 3.0;  // the vehicle's, missed this long: gone
  double reconnect_initial_s = 0.1;
  double reconnect_max_s = 5.0;
};

struct VehicleIdentity {
  bool known = false;
  std::uint8_t system = 0, component = 0;
  std::uint8_t autopilot = 0, type = 0;
  long heartbeats = 0;
  double last_heartbeat_wall_s = -1e300;

  // "system 1 component 1 (ArduPilot)".
  std::string Describe() const;
};

class ConnectionObserver {
 public:
  virtual ~ConnectionObserver() = default;
  // A good frame; from_vehicle: from the vehicle's system and component.
  virtual void OnFrame(const Frame& frame, bool from_vehicle) = 0;
  virtual void OnLinkUp() {}
  // The link failed (`why`: the system's reason, named with the link).
  virtual void OnLinkLost(const std::string& why) { (void)why; }
  virtual void OnOpenFailed(const std::string& why) { (void)why; }
  // Bad frames or garbage (`count`), the latest in words.
  virtual void OnBadFrames(long count, const std::string& latest) { (void)count; (void)latest; }
};

class Connection {
 public:
  Connection(LinkSpec link, const ConnectionOptions& options);
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  // "tcp:127.0.0.1:5760".
  std::string LinkName() const;
  void SetObserver(ConnectionObserver* observer) { observer_ = observer; }

  // Works the link for at most timeout_s: (re)opens it, reads and dispatches frames, sends our
  // heartbeat when due. Returns early when `stop` (called after each dispatched batch of frames)
  // says so. Never throws for what the link does.
  void Pump(double timeout_s, const std::function<bool()>& stop = {},
            const std::function<void(const Frame&, bool)>& on_frame = {});

  // Sends a frame to the link; false (with the reason in last_send_error()) when it cannot go.
  bool Send(std::uint32_t message, const Payload& payload);
  // A target system/component pair for requests: the vehicle's (0, 0 before it is known).
  std::uint8_t target_system() const { return vehicle_.system; }
  std::uint8_t target_component() const { return vehicle_.component; }

  bool open() const { return open_; }
  const VehicleIdentity& vehicle() const { return vehicle_; }
  // s since the vehicle's last heartbeat (wall clock); +inf before the first.
  double HeartbeatAgeS() const;
  // The vehicle was heard and its heartbeats have stopped for longer than heartbeat_timeout_s.
  bool VehicleGone() const;
  const FrameCounters& counters() const { return parser_.counters(); }
  long lost_frames() const { return lost_frames_; }
  const std::string& last_send_error() const { return last_send_error_; }
  // The latest failure to open or the reason the link dropped; empty while it works.
  const std::string& link_error() const { return link_error_; }

 private:
  bool TryOpen(double deadline_s);
  void ReadAvailable(const std::function<void(const Frame&, bool)>& on_frame);
  void Dispatch(const Frame& frame, const std::function<void(const Frame&, bool)>& on_frame);
  void Drop(const std::string& why);
  void HeartbeatIfDue();
  bool IsVehicle(const Frame& frame) const;

  LinkSpec spec_;
  ConnectionOptions options_;
  std::unique_ptr<Transport> transport_;
  ReconnectBackoff backoff_;
  FrameParser parser_;
  FrameWriter writer_;
  ConnectionObserver* observer_ = nullptr;
  bool open_ = false;
  VehicleIdentity vehicle_;
  std::optional<std::uint8_t> last_seq_;
  long lost_frames_ = 0;
  double next_heartbeat_wall_s_ = 0.0;
  std::string last_send_error_;
  std::string link_error_;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace accelcal::mavlink
