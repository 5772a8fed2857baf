#include "accelcal/acquire/mavlink/mavlink_connection.h"

#include <poll.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "accelcal/acquire/source/wall_clock.h"

namespace accelcal::mavlink {
namespace {

using source_detail::WallNowS;

constexpr size_t kLinkChunkBytes = 64 * 1024;
constexpr size_t kMaxBytesPerPump = 1024 * 1024;

int LinkPollMs(double until_s) {
  const double left_s = until_s - WallNowS();
  return left_s <= 0.0 ? 0 : static_cast<int>(std::ceil(std::min(left_s, 3600.0) * 1000.0));
}

}  // namespace

std::string VehicleIdentity::Describe() const {
  if (!known) return "no vehicle yet";
  return fmt::format("system {} component {} ({})", system, component, AutopilotName(autopilot));
}

Connection::Connection(LinkSpec link, const ConnectionOptions& options)
    : spec_(std::move(link)),
      options_(options),
      transport_(MakeTransport(spec_)),
      backoff_(options.reconnect_initial_s, options.reconnect_max_s),
      buffer_(kLinkChunkBytes) {}

Connection::~Connection() { transport_->Close(); }

std::string Connection::LinkName() const { return DescribeLink(spec_); }

double Connection::HeartbeatAgeS() const {
  return vehicle_.heartbeats == 0 ? INFINITY : WallNowS() - vehicle_.last_heartbeat_wall_s;
}

bool Connection::VehicleGone() const {
  return vehicle_.known && HeartbeatAgeS() > options_.heartbeat_timeout_s;
}

void Connection::Pump(double timeout_s, const std::function<bool()>& stop,
                      const std::function<void(const Frame&, bool)>& on_frame) {
  const double deadline_s = WallNowS() + std::max(0.0, timeout_s);
  for (;;) {
    if (!open_ && !TryOpen(deadline_s)) {
      if (WallNowS() >= deadline_s) return;
      continue;
    }
    HeartbeatIfDue();
    const double wake_s = std::min(deadline_s, next_heartbeat_wall_s_);
    pollfd p{transport_->fd(), POLLIN, 0};
    const int rc = poll(&p, 1, LinkPollMs(wake_s));
    if (rc < 0 && errno != EINTR) Drop(std::string("poll: ") + std::strerror(errno));
    if (rc > 0) ReadAvailable(on_frame);
    if (stop && stop()) return;
    if (WallNowS() >= deadline_s) return;
  }
}

bool Connection::TryOpen(double deadline_s) {
  const double now_s = WallNowS();
  if (!backoff_.Due(now_s, deadline_s)) return false;
  std::string error;
  switch (transport_->Open(std::max(0.0, deadline_s - now_s), &error)) {
    case Transport::OpenStep::kOpen:
      open_ = true;
      link_error_.clear();
      backoff_.Succeeded();
      next_heartbeat_wall_s_ = 0.0;  // say hello at once (a udpout vehicle waits for it)
      if (observer_ != nullptr) observer_->OnLinkUp();
      return true;
    case Transport::OpenStep::kPending:
      return false;
    case Transport::OpenStep::kFailed:
      link_error_ = error;
      if (observer_ != nullptr) observer_->OnOpenFailed(error);
      backoff_.Failed(WallNowS());
      return false;
  }
  return false;
}

void Connection::Drop(const std::string& why) {
  transport_->Close();
  open_ = false;
  parser_.Reset();
  last_seq_.reset();
  link_error_ = fmt::format("{}: {}", LinkName(), why);
  backoff_.Failed(WallNowS());
  if (observer_ != nullptr) observer_->OnLinkLost(link_error_);
}

void Connection::ReadAvailable(const std::function<void(const Frame&, bool)>& on_frame) {
  size_t taken = 0;
  std::vector<Frame> frames;
  while (open_ && taken < kMaxBytesPerPump) {
    const ssize_t n = transport_->Receive(buffer_.data(), buffer_.size());
    if (n > 0) {
      taken += static_cast<size_t>(n);
      long bad = 0;
      frames.clear();
      parser_.Feed(buffer_.data(), static_cast<size_t>(n), &frames, &bad);
      if (bad > 0 && observer_ != nullptr) observer_->OnBadFrames(bad, parser_.last_complaint());
      for (const Frame& f : frames) Dispatch(f, on_frame);
      pollfd p{transport_->fd(), POLLIN, 0};
      if (poll(&p, 1, 0) <= 0) return;
    } else if (n == 0) {
      Drop("the other end closed the link");
    } else if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) {
      return;
    } else if (errno == ECONNREFUSED && spec_.kind == LinkKind::kUdpOut) {
      // Nobody listens at the vehicle's address (yet): ICMP port unreachable, not a broken link.
      link_error_ = fmt::format("{}: nobody listens there (connection refused)", LinkName());
      return;
    } else {
      Drop(std::string("read: ") + std::strerror(errno));
    }
  }
}

bool Connection::IsVehicle(const Frame& frame) const {
  return vehicle_.known && frame.system == vehicle_.system && frame.component == vehicle_.component;
}

void Connection::Dispatch(const Frame& frame, const std::function<void(const Frame&, bool)>& on_frame) {
  if (frame.message == kHeartbeat) {
    const Heartbeat h = DecodeHeartbeat(frame.payload);
    const bool autopilot = h.autopilot != kAutopilotInvalid && h.type != kTypeGcs;
    const bool wanted = (options_.system < 0 || frame.system == options_.system) &&
                        (options_.component < 0 || frame.component == options_.component);
    if (!vehicle_.known && wanted && (autopilot || options_.component >= 0)) {
      vehicle_.known = true;
      vehicle_.system = frame.system;
      vehicle_.component = frame.component;
    }
    if (IsVehicle(frame)) {
      vehicle_.autopilot = h.autopilot;
      vehicle_.type = h.type;
      ++vehicle_.heartbeats;
      vehicle_.last_heartbeat_wall_s = WallNowS();
    }
  }
  const bool from_vehicle = IsVehicle(frame);
  if (from_vehicle) {
    if (last_seq_) lost_frames_ += static_cast<std::uint8_t>(frame.seq - *last_seq_ - 1);
    last_seq_ = frame.seq;
  }
  if (observer_ != nullptr) observer_->OnFrame(frame, from_vehicle);
  if (on_frame) on_frame(frame, from_vehicle);
}

void Connection::HeartbeatIfDue() {
  const double now_s = WallNowS();
  if (now_s < next_heartbeat_wall_s_) return;
  next_heartbeat_wall_s_ = now_s + options_.heartbeat_period_s;
  Heartbeat h;
  h.type = kTypeGcs;
  h.autopilot = kAutopilotInvalid;
  h.system_status = 4;  // MAV_STATE_ACTIVE
  h.mavlink_version = 3;
  Send(kHeartbeat, EncodeHeartbeat(h));
}

bool Connection::Send(std::uint32_t message, const Payload& payload) {
  if (!open_) {
    last_send_error_ = fmt::format("{} is not open", LinkName());
    return false;
  }
  std::string error;
  if (transport_->Send(writer_.Encode(message, payload), &error)) return true;
  last_send_error_ = fmt::format("{}: {}", LinkName(), error);
  // A stream that cannot be written is broken; a UDP send that found nobody is not.
  if (spec_.kind == LinkKind::kSerial || spec_.kind == LinkKind::kTcp) Drop(error);
  return false;
}

}  // namespace accelcal::mavlink
