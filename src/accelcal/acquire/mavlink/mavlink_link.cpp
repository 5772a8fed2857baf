#include "accelcal/acquire/mavlink/mavlink_link.h"

#include <arpa/inet.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "accelcal/acquire/source/host_port.h"
#include "accelcal/acquire/source/serial_link.h"
#include "accelcal/acquire/source/tcp_link.h"
#include "accelcal/base/error.h"
#include "accelcal/base/text_scan.h"

namespace accelcal::mavlink {
namespace {

constexpr const char* kExpectedLinks =
    "mavlink:serial:DEVICE@BAUD, mavlink:tcp:HOST:PORT, mavlink:udp:ADDR:PORT or "
    "mavlink:udpout:HOST:PORT";

bool HasScheme(const std::string& text, std::string_view prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// A frame never waits long for room in a stream: at most this, s.
constexpr int kSendWaitMs = 200;

// Serial and TCP: the text links' byte links, also written to.
class StreamTransport final : public Transport {
 public:
  explicit StreamTransport(std::unique_ptr<ByteLink> link) : link_(std::move(link)) {}
  std::string Describe() const override { return link_->Describe(); }
  OpenStep Open(double timeout_s, std::string* error) override { return link_->Open(timeout_s, error); }
  int fd() const override { return link_->fd(); }
  void Close() override { link_->Close(); }
  ssize_t Receive(std::uint8_t* buffer, size_t size) override { return ::read(link_->fd(), buffer, size); }
  bool Send(const std::vector<std::uint8_t>& bytes, std::string* error) override {
    size_t sent = 0;
    while (sent < bytes.size()) {
      const ssize_t n = ::write(link_->fd(), bytes.data() + sent, bytes.size() - sent);
      if (n > 0) {
        sent += static_cast<size_t>(n);
        continue;
      }
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) {
        pollfd p{link_->fd(), POLLOUT, 0};
        if (poll(&p, 1, kSendWaitMs) > 0) continue;
        *error = "the link takes no more bytes (send buffer full)";
        return false;
      }
      *error = std::string("write: ") + std::strerror(errno);
      return false;
    }
    return true;
  }

 private:
  std::unique_ptr<ByteLink> link_;
};

// udp: (listen, answer the last sender) and udpout: (connected to the vehicle).
class UdpTransport final : public Transport {
 public:
  UdpTransport(LinkSpec spec) : spec_(std::move(spec)) {}
  ~UdpTransport() override { Close(); }
  std::string Describe() const override { return DescribeLink(spec_); }
  OpenStep Open(double timeout_s, std::string* error) override;
  int fd() const override { return fd_; }
  void Close() override {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  ssize_t Receive(std::uint8_t* buffer, size_t size) override {
    sockaddr_storage from{};
    socklen_t from_len = sizeof from;
    const ssize_t n = ::recvfrom(fd_, buffer, size, 0, reinterpret_cast<sockaddr*>(&from), &from_len);
    if (n > 0 && spec_.kind == LinkKind::kUdp) {
      peer_ = from;
      peer_len_ = from_len;
    }
    // A datagram is never "the end" of a UDP link; an empty one is nothing.
    if (n == 0) {
      errno = EAGAIN;
      return -1;
    }
    return n;
  }
  bool Send(const std::vector<std::uint8_t>& bytes, std::string* error) override {
    ssize_t n = 0;
    if (spec_.kind == LinkKind::kUdpOut) {
      n = ::send(fd_, bytes.data(), bytes.size(), 0);
    } else if (peer_len_ == 0) {
      *error = fmt::format("nobody has sent to {} yet, so there is no one to answer", Describe());
      return false;
    } else {
      n = ::sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&peer_), peer_len_);
    }
    if (n == static_cast<ssize_t>(bytes.size())) return true;
    *error = std::string("send: ") + (n < 0 ? std::strerror(errno) : "datagram cut short");
    return false;
  }

 private:
  LinkSpec spec_;
  int fd_ = -1;
  sockaddr_storage peer_{};
  socklen_t peer_len_ = 0;
};

Transport::OpenStep UdpTransport::Open(double /*timeout_s*/, std::string* error) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_DGRAM;
  if (spec_.kind == LinkKind::kUdp) hints.ai_flags = AI_PASSIVE;
  addrinfo* found = nullptr;
  const std::string port = std::to_string(spec_.port);
  if (const int rc = getaddrinfo(spec_.host.c_str(), port.c_str(), &hints, &found); rc != 0) {
    *error = fmt::format("{}: {}", Describe(), gai_strerror(rc));
    return OpenStep::kFailed;
  }
  fd_ = ::socket(found->ai_family, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  int rc = fd_ < 0 ? -1 : 0;
  if (rc == 0 && spec_.kind == LinkKind::kUdp) {
    const int on = 1;
    setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
    rc = ::bind(fd_, found->ai_addr, found->ai_addrlen);
  } else if (rc == 0) {
    rc = ::connect(fd_, found->ai_addr, found->ai_addrlen);
  }
  const int err = errno;
  freeaddrinfo(found);
  if (rc != 0) {
    *error = fmt::format("{}: {} {}", Describe(), spec_.kind == LinkKind::kUdp ? "bind" : "connect",
                         std::strerror(err));
    Close();
    return OpenStep::kFailed;
  }
  return OpenStep::kOpen;
}

}  // namespace

LinkSpec ParseLinkSpec(const std::string& link, const std::string& whole_spec) {
  LinkSpec s;
  if (HasScheme(link, "serial:")) {
    s.kind = LinkKind::kSerial;
    const std::string rest = link.substr(7);
    const size_t at = rest.rfind('@');
    s.path = rest.substr(0, at);
    if (at == std::string::npos || s.path.empty())
      throw Error(fmt::format("source '{}': expected mavlink:serial:DEVICE@BAUD, e.g. "
                              "mavlink:serial:/dev/ttyACM0@115200", whole_spec));
    if (!detail::ParseLong(rest.substr(at + 1), &s.baud) || s.baud <= 0)
      throw Error(fmt::format("source '{}': baud rate '{}' is not a positive whole number",
                              whole_spec, rest.substr(at + 1)));
    return s;
  }
  struct Scheme { const char* prefix; LinkKind kind; const char* example; };
  for (const Scheme& scheme : {Scheme{"tcp:", LinkKind::kTcp, "mavlink:tcp:HOST:PORT, e.g. mavlink:tcp:127.0.0.1:5760"},
                               Scheme{"udp:", LinkKind::kUdp, "mavlink:udp:ADDR:PORT, e.g. mavlink:udp:0.0.0.0:14550"},
                               Scheme{"udpout:", LinkKind::kUdpOut, "mavlink:udpout:HOST:PORT, e.g. mavlink:udpout:192.168.4.1:14555"}}) {
    if (!HasScheme(link, scheme.prefix)) continue;
    const HostPort hp = ParseHostPort(link.substr(std::string_view(scheme.prefix).size()), whole_spec, scheme.example);
    s.kind = scheme.kind;
    s.host = hp.host;
    s.port = hp.port;
    return s;
  }
  throw Error(fmt::format("source '{}': unknown MAVLink link '{}': expected {}", whole_spec, link,
                          kExpectedLinks));
}

std::string DescribeLink(const LinkSpec& spec) {
  const HostPort hp{spec.host, spec.port};
  switch (spec.kind) {
    case LinkKind::kSerial: return fmt::format("serial:{}@{}", spec.path, spec.baud);
    case LinkKind::kTcp: return "tcp:" + hp.Describe();
    case LinkKind::kUdp: return "udp:" + hp.Describe();
    case LinkKind::kUdpOut: return "udpout:" + hp.Describe();
  }
  return "?";
}

std::unique_ptr<Transport> MakeTransport(const LinkSpec& spec) {
  switch (spec.kind) {
    case LinkKind::kSerial:
      return std::make_unique<StreamTransport>(MakeSerialLink(spec.path, spec.baud, true));
    case LinkKind::kTcp:
      return std::make_unique<StreamTransport>(MakeTcpLink(spec.host, spec.port));
    case LinkKind::kUdp:
    case LinkKind::kUdpOut:
      return std::make_unique<UdpTransport>(spec);
  }
  throw Error("unreachable MAVLink link kind");
}

}  // namespace accelcal::mavlink
