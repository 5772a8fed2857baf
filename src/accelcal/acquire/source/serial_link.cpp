#include "accelcal/acquire/source/serial_link.h"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <utility>

#include <fmt/format.h>

#include "accelcal/base/error.h"

namespace accelcal {
namespace {

// In increasing order (messages list them as they are).
constexpr std::array<std::pair<long, speed_t>, 22> kBaudRates = {{
    {300, B300},         {1200, B1200},       {2400, B2400},       {4800, B4800},       {9600, B9600},
    {19200, B19200},     {38400, B38400},     {57600, B57600},     {115200, B115200},
    {230400, B230400},   {460800, B460800},   {500000, B500000},   {576000, B576000},
    {921600, B921600},   {1000000, B1000000}, {1152000, B1152000}, {1500000, B1500000},
    {2000000, B2000000}, {2500000, B2500000}, {3000000, B3000000}, {3500000, B3500000},
    {4000000, B4000000},
}};

speed_t BaudConstant(long baud) {
  for (const auto& [rate, constant] : kBaudRates)
    if (rate == baud) return constant;
  return B0;
}

std::string Errno(const std::string& what) { return what + ": " + std::strerror(errno); }

class SerialLink final : public ByteLink {
 public:
  SerialLink(std::string device, long baud, bool read_write)
      : device_(std::move(device)), baud_(baud), read_write_(read_write) {}
  ~SerialLink() override { Close(); }

  std::string Describe() const override { return fmt::format("serial:{}@{}", device_, baud_); }
  OpenStep Open(double timeout_s, std::string* error) override;
  int fd() const override { return fd_; }
  void Close() override {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  bool reopens() const override { return true; }

 private:
  bool Configure(std::string* error);

  std::string device_;
  long baud_;
  bool read_write_;
  int fd_ = -1;
};

ByteLink::OpenStep SerialLink::Open(double /*timeout_s*/, std::string* error) {
  fd_ = ::open(device_.c_str(), (read_write_ ? O_RDWR : O_RDONLY) | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) {
    *error = Errno("open " + device_);
    return OpenStep::kFailed;
  }
  if (!Configure(error)) {
    Close();
    return OpenStep::kFailed;
  }
  return OpenStep::kOpen;
}

bool SerialLink::Configure(std::string* error) {
  termios tio{};
  if (tcgetattr(fd_, &tio) != 0) {
    *error = Errno(device_ + " is not a serial port (tcgetattr)");
    return false;
  }
  cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;  // ignore modem lines; enable the receiver
  tio.c_cc[VMIN] = 0;             // reads return what is there (poll() does the waiting)
  tio.c_cc[VTIME] = 0;
  const speed_t speed = BaudConstant(baud_);
  if (cfsetispeed(&tio, speed) != 0 || cfsetospeed(&tio, speed) != 0 ||
      tcsetattr(fd_, TCSANOW, &tio) != 0) {
    *error = Errno(fmt::format("{}: cannot set raw mode at {} baud", device_, baud_));
    return false;
  }
  tcflush(fd_, TCIFLUSH);  // bytes queued before we were listening may be mid-line
  return true;
}

}  // namespace

bool IsSupportedBaudRate(long baud) { return BaudConstant(baud) != B0; }

std::string SupportedBaudRatesText() {
  std::string text;
  for (const auto& [rate, constant] : kBaudRates) {
    if (!text.empty()) text += ", ";
    text += std::to_string(rate);
  }
  return text;
}

std::unique_ptr<ByteLink> MakeSerialLink(const std::string& device, long baud, bool read_write) {
  if (!IsSupportedBaudRate(baud))
    throw Error(fmt::format("serial:{}@{}: unsupported baud rate {}; supported: {}", device, baud,
                            baud, SupportedBaudRatesText()));
  return std::make_unique<SerialLink>(device, baud, read_write);
}

}  // namespace accelcal
