// tcp:HOST:PORT against a local server on 127.0.0.1 (ephemeral port): a dropped connection is
// reopened and the stream goes on; a refused connection is retried until the server appears.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <thread>

#include <gtest/gtest.h>

#include "accelcal/acquire/source/source_spec.h"
#include "source_test_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

using testing::Consecutive;
using testing::Contains;
using testing::ReadUntil;
using testing::SampleLines;
using testing::WriteAll;

// A listening socket on 127.0.0.1; port 0 picks a free one.
int Listen(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  const int on = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &on, sizeof(on));
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) != 0 || ::listen(fd, 4) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

int PortOf(int fd) {
  sockaddr_in addr{};
  socklen_t len = sizeof(addr);
  getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
  return ntohs(addr.sin_port);
}

// Accepts one client, sends `text`, and closes the connection.
void ServeOnce(int listener, const std::string& text) {
  const int client = ::accept(listener, nullptr, nullptr);
  ASSERT_GE(client, 0);
  EXPECT_TRUE(WriteAll(client, text));
  ::close(client);
}

SourceOptions FastRetry() {
  SourceOptions o;
  o.reconnect_initial_s = 0.05;
  o.reconnect_max_s = 0.2;
  o.dead_after_s = 5.0;
  return o;
}

TEST(TcpSourceTest, DroppedConnectionIsReopenedAndTheStreamGoesOn) {
  const int listener = Listen(0);
  ASSERT_GE(listener, 0);
  // First connection: 100 lines and a fragment of line 101, then the link drops. The fragment
  // would parse as a sample with t = 1 if it were not discarded.
  std::thread server([&] {
    ServeOnce(listener, SampleLines(0, 100) + "1 100 2000 30");
    ServeOnce(listener, SampleLines(100, 100) + SampleLines(200, 50000, 100.0));  // and a burst
  });
  auto source = OpenSource("tcp:127.0.0.1:" + std::to_string(PortOf(listener)), FastRetry());
  std::vector<Sample> samples;
  ReadResult events;
  const bool all = ReadUntil(
      *source, &samples, [](const SourceStatus& s) { return s.samples_total >= 50200; }, 60.0,
      &events);
  server.join();
  ::close(listener);
  ASSERT_TRUE(all) << source->status().BriefReport();
  EXPECT_EQ(samples.size(), 50200u);
  EXPECT_TRUE(Consecutive(samples));
  for (const Sample& s : samples) ASSERT_EQ(s.raw_counts.z(), 3000.0);
  EXPECT_TRUE(events.link_lost);
  EXPECT_TRUE(events.reconnected);
  EXPECT_GE(source->status().reconnects, 1);
  EXPECT_EQ(source->status().malformed_lines, 0);
}

TEST(TcpSourceTest, RefusedAtFirstThenTheServerAppears) {
  // Find a free port, and leave nothing listening on it.
  const int probe = Listen(0);
  ASSERT_GE(probe, 0);
  const int port = PortOf(probe);
  ::close(probe);
  SourceOptions options = FastRetry();
  options.dead_after_s = 0.3;
  auto source = OpenSource("tcp:127.0.0.1:" + std::to_string(port), options);
  std::vector<Sample> samples;
  ASSERT_TRUE(ReadUntil(*source, &samples,
                        [](const SourceStatus& s) { return !s.link_error.empty(); }));
  EXPECT_TRUE(Contains(source->status().link_error, "Connection refused"))
      << source->status().link_error;
  EXPECT_NE(source->status().link, LinkState::kUp);
  ASSERT_TRUE(ReadUntil(*source, &samples,
                        [](const SourceStatus& s) { return s.link == LinkState::kDead; }));

  const int listener = Listen(port);
  ASSERT_GE(listener, 0) << "port " << port << " was taken meanwhile";
  std::thread server([&] { ServeOnce(listener, SampleLines(0, 20)); });
  ReadResult events;
  const bool got = ReadUntil(
      *source, &samples, [](const SourceStatus& s) { return s.samples_total >= 20; }, 30.0, &events);
  server.join();
  ::close(listener);
  ASSERT_TRUE(got) << source->status().BriefReport();
  EXPECT_TRUE(Consecutive(samples));
  EXPECT_TRUE(events.reconnected);
}

}  // namespace
}  // namespace accelcal
