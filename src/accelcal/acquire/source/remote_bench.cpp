#include "accelcal/acquire/source/remote_bench.h"

#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <functional>
#include <sstream>

#include <fmt/format.h>

#include "accelcal/acquire/source/bench_control.h"
#include "accelcal/acquire/source/wall_clock.h"
#include "accelcal/base/error.h"

namespace accelcal {
namespace {

using source_detail::WallNowS;

constexpr double kQuietS = 0.3;        // the link this quiet after "held": nothing old is left
constexpr double kMaxDrainS = 10.0;    // a link that never goes quiet: give up draining
constexpr int kAnswerWaitMs = 10000;   // for the server's answer
constexpr int kHoldWaitMs = 30000;     // the server waits this long for the releasing command

int ConnectTo(const HostPort& to) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (getaddrinfo(to.host.c_str(), std::to_string(to.port).c_str(), &hints, &found) != 0) return -1;
  int fd = ::socket(found->ai_family, found->ai_socktype | SOCK_CLOEXEC, found->ai_protocol);
  if (fd >= 0 && ::connect(fd, found->ai_addr, found->ai_addrlen) != 0) {
    ::close(fd);
    fd = -1;
  }
  freeaddrinfo(found);
  if (fd >= 0) {
    const int on = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
  }
  return fd;
}

// One line from fd (blocking up to timeout_ms); false on silence, error or close.
bool ReadLineFrom(int fd, std::string* inbox, std::string* line, int timeout_ms) {
  const double deadline_s = WallNowS() + timeout_ms / 1000.0;
  for (;;) {
    const size_t nl = inbox->find('\n');
    if (nl != std::string::npos) {
      *line = inbox->substr(0, nl);
      inbox->erase(0, nl + 1);
      return true;
    }
    const int left_ms = static_cast<int>(std::ceil((deadline_s - WallNowS()) * 1000.0));
    pollfd p{fd, POLLIN, 0};
    if (left_ms < 0 || poll(&p, 1, std::max(left_ms, 0)) <= 0) return false;
    char buffer[512];
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n <= 0) return false;
    inbox->append(buffer, static_cast<size_t>(n));
  }
}

bool WriteAll(int fd, const std::string& text) {
  return ::send(fd, text.data(), text.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(text.size());
}

// The controls sent over TCP, for any source: `drain` reads and drops what arrived within its
// timeout (true when something did), `now` is the source's latest t.
class RemoteBenchClient final : public BenchControl {
 public:
  RemoteBenchClient(HostPort bench, std::function<bool(double)> drain, std::function<double()> now)
      : bench_(std::move(bench)), drain_(std::move(drain)), now_(std::move(now)) {}
  ~RemoteBenchClient() override {
    if (fd_ >= 0) ::close(fd_);
  }

  void PlaceStatic(const Eigen::Vector3d& up, double yaw_rad) override {
    Command(fmt::format("static {:.17g} {:.17g} {:.17g} {:.17g}", up.x(), up.y(), up.z(), yaw_rad));
  }
  void PlaceTurntable(double radius_m, double rpm, sim::SensorAxis radial, sim::SensorAxis up) override {
    Command(fmt::format("turntable {:.17g} {:.17g} {} {}", radius_m, rpm, SensorAxisToString(radial),
                        SensorAxisToString(up)));
  }
  void StopTurntable() override { Command("stop"); }
  void AdjustTableFeet(const Eigen::Vector2d& tilt_deg) override {
    Command(fmt::format("feet {:.17g} {:.17g}", tilt_deg.x(), tilt_deg.y()));
  }
  void LevelTurntable() override { Command("level"); }
  double now_s() const override { return now_(); }

 private:
  // hold, drain, then the command; throws accelcal::Error when the bench does not answer.
  void Command(const std::string& command) {
    if (fd_ < 0) fd_ = ConnectTo(bench_);
    if (fd_ < 0) Fail("cannot connect");
    Exchange("hold", "held");
    Drain();
    Exchange(command, "ok");
  }
  void Exchange(const std::string& command, const std::string& want) {
    std::string answer;
    if (!WriteAll(fd_, command + "\n") || !ReadLineFrom(fd_, &inbox_, &answer, kAnswerWaitMs))
      Fail(fmt::format("no answer to '{}'", command));
    if (answer != want) Fail(fmt::format("'{}' answered '{}'", command, answer));
  }
  void Drain() {
    const double start_s = WallNowS();
    double last_s = start_s;
    while (WallNowS() - last_s < kQuietS && WallNowS() - start_s < kMaxDrainS)
      if (drain_(0.05)) last_s = WallNowS();
  }
  [[noreturn]] void Fail(const std::string& why) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    inbox_.clear();
    throw Error(fmt::format("the remote bench at {}: {}", bench_.Describe(), why));
  }

  HostPort bench_;
  std::function<bool(double)> drain_;
  std::function<double()> now_;
  int fd_ = -1;
  std::string inbox_;
};

class RemoteBenchSource final : public SampleSource {
 public:
  RemoteBenchSource(std::unique_ptr<SampleSource> inner, HostPort bench)
      : inner_(std::move(inner)),
        client_(std::move(bench),
                [this](double timeout_s) {
                  std::vector<Sample> dropped;
                  return inner_->Read(timeout_s, &dropped).samples > 0;
                },
                [this] { return inner_->status().last_t_s; }) {}

  std::string Describe() const override { return inner_->Describe(); }
  ReadResult Read(double timeout_s, std::vector<Sample>* out) override { return inner_->Read(timeout_s, out); }
  const SourceStatus& status() const override { return inner_->status(); }
  std::string DescribeReading() const override { return inner_->DescribeReading(); }
  BenchControl* bench() override { return &client_; }

 private:
  std::unique_ptr<SampleSource> inner_;
  RemoteBenchClient client_;
};

// Several sensors on the one simulated sensor's link (a vehicle's IMUs): the plate is placed.
class RemoteBenchSet final : public SensorSetSource {
 public:
  RemoteBenchSet(std::unique_ptr<SensorSetSource> inner, HostPort bench)
      : inner_(std::move(inner)),
        client_(std::move(bench),
                [this](double timeout_s) {
                  SensorSetSamples dropped;
                  return inner_->Read(timeout_s, &dropped).samples > 0;
                },
                [this] {
                  double latest_s = kNaN;
                  for (std::size_t i = 0; i < inner_->sensor_count(); ++i) {
                    const double t_s = inner_->status(i).last_t_s;
                    if (!(t_s <= latest_s)) latest_s = std::isnan(t_s) ? latest_s : t_s;
                  }
                  return latest_s;
                }) {}

  std::string Describe() const override { return inner_->Describe(); }
  const Fixture& fixture() const override { return inner_->fixture(); }
  ReadResult Read(double timeout_s, SensorSetSamples* out) override { return inner_->Read(timeout_s, out); }
  const SourceStatus& status(std::size_t sensor) const override { return inner_->status(sensor); }
  BenchControl* bench() override { return &client_; }

 private:
  std::unique_ptr<SensorSetSource> inner_;
  RemoteBenchClient client_;
};

}  // namespace

std::unique_ptr<SampleSource> WithRemoteBench(std::unique_ptr<SampleSource> source, const HostPort& bench) {
  return std::make_unique<RemoteBenchSource>(std::move(source), bench);
}

std::unique_ptr<SensorSetSource> WithRemoteBench(std::unique_ptr<SensorSetSource> set, const HostPort& bench) {
  return std::make_unique<RemoteBenchSet>(std::move(set), bench);
}

RemoteBenchServer::RemoteBenchServer(const HostPort& listen, BenchControl* bench) : bench_(bench) {
  if (bench_ == nullptr) throw Error("--bench-listen: only the virtual bench (--source sim) has controls to serve");
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE;
  addrinfo* found = nullptr;
  if (getaddrinfo(listen.host.c_str(), std::to_string(listen.port).c_str(), &hints, &found) != 0)
    throw Error(fmt::format("--bench-listen {}: cannot resolve", listen.Describe()));
  listen_fd_ = ::socket(found->ai_family, found->ai_socktype | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  const int on = 1;
  if (listen_fd_ >= 0) setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
  const bool ok = listen_fd_ >= 0 && ::bind(listen_fd_, found->ai_addr, found->ai_addrlen) == 0 &&
                  ::listen(listen_fd_, 4) == 0;
  const int err = errno;
  freeaddrinfo(found);
  if (!ok) throw Error(fmt::format("--bench-listen {}: {}", listen.Describe(), std::strerror(err)));
  sockaddr_storage bound{};
  socklen_t len = sizeof bound;
  getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&bound), &len);
  port_ = ntohs(bound.ss_family == AF_INET6 ? reinterpret_cast<sockaddr_in6*>(&bound)->sin6_port
                                            : reinterpret_cast<sockaddr_in*>(&bound)->sin_port);
}

RemoteBenchServer::~RemoteBenchServer() {
  DropClient();
  if (listen_fd_ >= 0) ::close(listen_fd_);
}

void RemoteBenchServer::DropClient() {
  if (client_fd_ >= 0) ::close(client_fd_);
  client_fd_ = -1;
  inbox_.clear();
}

bool RemoteBenchServer::ReadLine(std::string* line, int timeout_ms) {
  return client_fd_ >= 0 && ReadLineFrom(client_fd_, &inbox_, line, timeout_ms);
}

void RemoteBenchServer::Answer(const std::string& line) {
  if (!WriteAll(client_fd_, line + "\n")) DropClient();
}

void RemoteBenchServer::Serve(const std::function<void()>& flush) {
  // A new client (a wizard started again after a kill) replaces the old one.
  const int fd = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
  if (fd >= 0) {
    DropClient();
    client_fd_ = fd;
  }
  std::string line;
  while (client_fd_ >= 0) {
    if (!ReadLine(&line, 0)) {
      // Nothing complete: either nothing came, or the other end closed (read 0): forget it then.
      char probe;
      if (::recv(client_fd_, &probe, 1, MSG_PEEK | MSG_DONTWAIT) == 0) DropClient();
      return;
    }
    if (line != "hold") {
      Answer("error expected hold first");
      continue;
    }
    flush();
    Answer("held");
    if (!ReadLine(&line, kHoldWaitMs)) {
      DropClient();
      return;
    }
    Answer(Execute(line));
  }
}

std::string RemoteBenchServer::Execute(const std::string& command) {
  std::istringstream in(command);
  std::string verb;
  in >> verb;
  try {
    if (verb == "static") {
      double x = 0, y = 0, z = 0, yaw = 0;
      if (!(in >> x >> y >> z >> yaw)) return "error static needs UX UY UZ YAW";
      bench_->PlaceStatic(Eigen::Vector3d(x, y, z), yaw);
    } else if (verb == "turntable") {
      double r = 0, rpm = 0;
      std::string radial, up;
      if (!(in >> r >> rpm >> radial >> up) || !StringToSensorAxis(radial) || !StringToSensorAxis(up))
        return "error turntable needs R RPM RADIAL UP";
      bench_->PlaceTurntable(r, rpm, *StringToSensorAxis(radial), *StringToSensorAxis(up));
    } else if (verb == "stop") {
      bench_->StopTurntable();
    } else if (verb == "feet") {
      double tx = 0, ty = 0;
      if (!(in >> tx >> ty)) return "error feet needs TX TY";
      bench_->AdjustTableFeet(Eigen::Vector2d(tx, ty));
    } else if (verb == "level") {
      bench_->LevelTurntable();
    } else {
      return "error unknown command " + verb;
    }
  } catch (const Error& e) {
    return std::string("error ") + e.what();
  }
  return "ok";
}

}  // namespace accelcal
