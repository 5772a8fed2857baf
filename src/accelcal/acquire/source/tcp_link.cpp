#include "accelcal/acquire/source/tcp_link.h"

#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

namespace accelcal {
namespace {

class TcpLink final : public ByteLink {
 public:
  TcpLink(std::string host, int port) : host_(std::move(host)), port_(port) {}
  ~TcpLink() override { Close(); }

  std::string Describe() const override {
    const bool v6 = host_.find(':') != std::string::npos;
    return v6 ? fmt::format("tcp:[{}]:{}", host_, port_) : fmt::format("tcp:{}:{}", host_, port_);
  }
  OpenStep Open(double timeout_s, std::string* error) override;
  int fd() const override { return fd_; }
  void Close() override {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    connecting_ = false;
  }
  bool reopens() const override { return true; }

 private:
  OpenStep StartConnect(std::string* error);
  OpenStep AwaitConnect(double timeout_s, std::string* error);
  void EnableKeepalive();
  OpenStep Fail(const std::string& why, int err, std::string* error) {
    Close();
    *error = fmt::format("connect {}:{}: {}", host_, port_, why.empty() ? std::strerror(err) : why);
    return OpenStep::kFailed;
  }

  std::string host_;
  int port_;
  int fd_ = -1;
  bool connecting_ = false;  // a non-blocking connect is in progress on fd_
  unsigned attempt_ = 0;     // picks the address to try when a name has several
};

ByteLink::OpenStep TcpLink::Open(double timeout_s, std::string* error) {
  if (!connecting_) {
    const OpenStep started = StartConnect(error);
    if (started != OpenStep::kPending) return started;
  }
  return AwaitConnect(timeout_s, error);
}

ByteLink::OpenStep TcpLink::StartConnect(std::string* error) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  const std::string port = std::to_string(port_);
  if (const int rc = getaddrinfo(host_.c_str(), port.c_str(), &hints, &found); rc != 0)
    return Fail(gai_strerror(rc), 0, error);
  int count = 0;
  for (addrinfo* a = found; a != nullptr; a = a->ai_next) ++count;
  addrinfo* chosen = found;
  for (unsigned i = 0; i < attempt_ % static_cast<unsigned>(count); ++i) chosen = chosen->ai_next;
  ++attempt_;
  fd_ = ::socket(chosen->ai_family, chosen->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC,
                 chosen->ai_protocol);
  const int rc = fd_ < 0 ? -1 : ::connect(fd_, chosen->ai_addr, chosen->ai_addrlen);
  const int err = errno;
  freeaddrinfo(found);
  if (rc == 0) {
    EnableKeepalive();
    return OpenStep::kOpen;
  }
  if (fd_ < 0 || err != EINPROGRESS) return Fail("", err, error);
  connecting_ = true;
  return OpenStep::kPending;
}

ByteLink::OpenStep TcpLink::AwaitConnect(double timeout_s, std::string* error) {
  pollfd p{fd_, POLLOUT, 0};
  const int ms = static_cast<int>(std::ceil(std::min(timeout_s, 3600.0) * 1000.0));
  const int rc = poll(&p, 1, ms);
  if (rc < 0 && errno != EINTR) return Fail("", errno, error);
  if (rc <= 0) return OpenStep::kPending;
  int so_error = 0;
  socklen_t len = sizeof(so_error);
  if (getsockopt(fd_, SOL_SOCKET, SO_ERROR, &so_error, &len) != 0) return Fail("", errno, error);
  if (so_error != 0) return Fail("", so_error, error);
  connecting_ = false;
  EnableKeepalive();
  return OpenStep::kOpen;
}

// A cable pulled or a board rebooted leaves a half-open connection that never reads EOF, since
// we never send. Keep-alive probes turn it into a read error within about 5 s.
void TcpLink::EnableKeepalive() {
  const int on = 1, idle_s = 2, interval_s = 1, probes = 3;
  setsockopt(fd_, SOL_SOCKET, SO_KEEPALIVE, &on, sizeof(on));
  setsockopt(fd_, IPPROTO_TCP, TCP_KEEPIDLE, &idle_s, sizeof(idle_s));
  setsockopt(fd_, IPPROTO_TCP, TCP_KEEPINTVL, &interval_s, sizeof(interval_s));
  setsockopt(fd_, IPPROTO_TCP, TCP_KEEPCNT, &probes, sizeof(probes));
}

}  // namespace

std::unique_ptr<ByteLink> MakeTcpLink(const std::string& host, int port) {
  return std::make_unique<TcpLink>(host, port);
}

}  // namespace accelcal
