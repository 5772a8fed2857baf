// The MAVLink source against a vehicle played in this process (our own framing both ways; the
// e2e tests play it with node-mavlink): counts of 0.001 m/s^2, SCALED_IMU's mG and resolution,
// the IMU instance, the rate request, sequence gaps, a reboot, the vehicle's calibration undone,
// and parameters read.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <functional>
#include <thread>

#include <gtest/gtest.h>

#include "accelcal/acquire/mavlink/mavlink_sensor_set.h"
#include "accelcal/acquire/mavlink/mavlink_source.h"
#include "accelcal/acquire/source/sensor_set_spec.h"
#include "accelcal/acquire/mavlink/param_client.h"
#include "source_test_support.h"
#include "test_support.h"

namespace accelcal {
namespace {

using namespace mavlink;
using testing::Contains;
using testing::ReadUntil;

// A vehicle on 127.0.0.1 (system 1, component 1, ArduPilot): heartbeats, answers COMMAND_LONG
// with an ACK and PARAM_REQUEST_READ from `params`, and sends what `stream` returns.
class FakeVehicle {
 public:
  using Stream = std::function<std::vector<std::vector<std::uint8_t>>(FrameWriter&, int tick)>;
  FakeVehicle(Stream stream, std::map<std::string, float> params = {})
      : stream_(std::move(stream)), params_(std::move(params)) {
    listener_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(listener_, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
    ::listen(listener_, 2);
    socklen_t len = sizeof addr;
    getsockname(listener_, reinterpret_cast<sockaddr*>(&addr), &len);
    port_ = ntohs(addr.sin_port);
    thread_ = std::thread([this] { Run(); });
  }
  ~FakeVehicle() {
    stop_ = true;
    thread_.join();
    ::close(listener_);
  }
  int port() const { return port_; }
  std::atomic<int> acks{0};

 private:
  void Send(int fd, const std::vector<std::uint8_t>& b) { (void)!::send(fd, b.data(), b.size(), MSG_NOSIGNAL); }
  void Run() {
    pollfd p{listener_, POLLIN, 0};
    if (poll(&p, 1, 20000) <= 0) return;
    const int fd = ::accept(listener_, nullptr, nullptr);
    FrameWriter writer(1, 1);
    FrameParser parser;
    for (int tick = 0; !stop_; ++tick) {
      if (tick % 20 == 0) {
        Heartbeat h;
        h.type = 2;
        h.autopilot = kAutopilotArduPilot;
        Send(fd, writer.Encode(kHeartbeat, EncodeHeartbeat(h)));
      }
      for (const auto& frame : stream_(writer, tick)) Send(fd, frame);
      std::uint8_t buffer[2048];
      pollfd q{fd, POLLIN, 0};
      while (poll(&q, 1, 0) > 0) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n <= 0) break;
        std::vector<Frame> frames;
        long bad = 0;
        parser.Feed(buffer, static_cast<size_t>(n), &frames, &bad);
        for (const Frame& f : frames) Answer(fd, writer, f);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ::close(fd);
  }
  void Answer(int fd, FrameWriter& writer, const Frame& f) {
    if (f.message == kCommandLong) {
      Payload ack(3, 0);
      const std::uint16_t command = kCmdSetMessageInterval;
      std::memcpy(ack.data(), &command, 2);
      ++acks;
      Send(fd, writer.Encode(kCommandAck, ack));
    } else if (f.message == kParamRequestRead) {
      std::string id(reinterpret_cast<const char*>(f.payload.data() + 4), 16);
      id = id.c_str();
      const auto it = params_.find(id);
      if (it == params_.end()) return;
      Payload v(25, 0);
      std::memcpy(v.data(), &it->second, 4);
      std::memcpy(v.data() + 8, id.data(), id.size());
      v[24] = kParamTypeReal32;
      Send(fd, writer.Encode(kParamValue, v));
    }
  }

  Stream stream_;
  std::map<std::string, float> params_;
  int listener_ = -1;
  int port_ = 0;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

std::vector<std::uint8_t> Highres(FrameWriter& w, double t_s, Eigen::Vector3d a, std::uint8_t id = 0) {
  Payload p(63, 0);
  const auto t_us = static_cast<std::uint64_t>(t_s * 1e6);
  std::memcpy(p.data(), &t_us, 8);
  for (int j = 0; j < 3; ++j) {
    const auto v = static_cast<float>(a(j));
    std::memcpy(p.data() + 8 + 4 * j, &v, 4);
  }
  p[62] = id;
  return w.Encode(kHighresImu, p);
}

std::vector<std::uint8_t> Scaled(FrameWriter& w, std::uint32_t message, double t_s, std::int16_t z_mg) {
  Payload p(24, 0);
  const auto t_ms = static_cast<std::uint32_t>(t_s * 1000.0);
  std::memcpy(p.data(), &t_ms, 4);
  std::memcpy(p.data() + 8, &z_mg, 2);
  return w.Encode(message, p);
}

SourceOptions LinkOptions() {
  SourceOptions o;
  o.reconnect_initial_s = 0.05;
  o.dead_after_s = 5.0;
  return o;
}

TEST(MavlinkSourceTest, HighresImuInCountsOfAThousandthMps2) {
  FakeVehicle vehicle([](FrameWriter& w, int tick) {
    return std::vector<std::vector<std::uint8_t>>{Highres(w, 0.01 * tick, {0.1, -0.2, 9.8}),
                                                  Highres(w, 0.01 * tick, {5, 5, 5}, 1)};
  });
  MavlinkSource source(ParseMavlinkSpec(fmt::format("mavlink:tcp:127.0.0.1:{}", vehicle.port())), LinkOptions());
  std::vector<Sample> samples;
  ASSERT_TRUE(ReadUntil(source, &samples, [](const SourceStatus& s) { return s.samples_total >= 30; }));
  EXPECT_NEAR(samples.back().raw_counts.x(), 100.0, 1e-3);
  EXPECT_NEAR(samples.back().raw_counts.y(), -200.0, 1e-3);
  EXPECT_NEAR(samples.back().raw_counts.z(), 9800.0, 1e-3);  // IMU 1 (5 m/s^2) never mixed in
  EXPECT_EQ(source.status().unit.Describe(), "m/s^2, taken as counts of 0.001 m/s^2");
  EXPECT_TRUE(std::isnan(source.status().resolution_counts));
  EXPECT_GE(vehicle.acks.load(), 1);
  EXPECT_TRUE(Contains(source.DescribeReading(), "SET_MESSAGE_INTERVAL: accepted")) << source.DescribeReading();
  EXPECT_TRUE(Contains(source.DescribeReading(), "HIGHRES_IMU of IMU 0 from system 1 component 1 (ArduPilot)"));
}

TEST(MavlinkSourceTest, ScaledImuOfTheAskedInstanceInMilliG) {
  FakeVehicle vehicle([](FrameWriter& w, int tick) {
    return std::vector<std::vector<std::uint8_t>>{Scaled(w, kScaledImu, 0.01 * tick, 500),
                                                  Scaled(w, kScaledImu2, 0.01 * tick, 1000)};
  });
  MavlinkSource source(ParseMavlinkSpec(fmt::format("mavlink:tcp:127.0.0.1:{},imu=1", vehicle.port())), LinkOptions());
  std::vector<Sample> samples;
  ASSERT_TRUE(ReadUntil(source, &samples, [](const SourceStatus& s) { return s.samples_total >= 20; }));
  EXPECT_NEAR(samples.back().raw_counts.z(), 9806.65, 1e-6);  // 1000 mG, exactly
  EXPECT_DOUBLE_EQ(source.status().resolution_counts, 9.80665);
  EXPECT_TRUE(Contains(source.status().ResolutionNote(), "(1 mG)")) << source.status().ResolutionNote();
  EXPECT_TRUE(Contains(source.status().last_notice, "no HIGHRES_IMU of IMU 1 came; reading SCALED_IMU2"))
      << source.status().last_notice;
}

TEST(MavlinkSourceTest, SequenceGapsAreLostFramesAndARebootKeepsTimeGoing) {
  FakeVehicle vehicle([](FrameWriter& w, int tick) {
    std::vector<std::vector<std::uint8_t>> out;
    const double t = tick < 100 ? 10.0 + 0.01 * tick : 0.5 + 0.01 * (tick - 100);  // reboot at 100
    auto frame = Highres(w, t, {0, 0, 9.8});
    if (tick % 10 != 5) out.push_back(frame);  // every tenth sent never arrives: a seq gap
    return out;
  });
  MavlinkSource source(ParseMavlinkSpec(fmt::format("mavlink:tcp:127.0.0.1:{}", vehicle.port())), LinkOptions());
  std::vector<Sample> samples;
  ASSERT_TRUE(ReadUntil(source, &samples, [](const SourceStatus& s) { return s.samples_total >= 140; }));
  EXPECT_GE(source.status().lost_frames, 10);
  for (size_t i = 1; i < samples.size(); ++i) ASSERT_GT(samples[i].t_s, samples[i - 1].t_s) << i;
  EXPECT_TRUE(Contains(source.DescribeReading(), "rebooted 1 time")) << source.DescribeReading();
}

TEST(MavlinkSourceTest, TheVehiclesCalibrationTakenBackOut) {
  FakeVehicle vehicle([](FrameWriter& w, int tick) {
    return std::vector<std::vector<std::uint8_t>>{Highres(w, 0.01 * tick, {2.0, 1.0, -9.0})};
  });
  MavlinkSource source(ParseMavlinkSpec(fmt::format("mavlink:tcp:127.0.0.1:{}", vehicle.port())), LinkOptions());
  AccelUndo undo;
  undo.offset_mps2 = Eigen::Vector3d(0.1, 0.0, 0.0);
  undo.scale = Eigen::Vector3d(2.0, 1.0, 1.0);
  undo.body_from_sensor = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();  // ROLL_180: y, z flip
  undo.body_from_sensor(1, 1) = -1.0;
  source.SetUndo(0, undo);
  std::vector<Sample> samples;
  ASSERT_TRUE(ReadUntil(source, &samples, [](const SourceStatus& s) { return s.samples_total >= 5; }));
  EXPECT_NEAR(samples.back().raw_counts.x(), (2.0 / 2.0 + 0.1) * 1000.0, 1e-3);
  EXPECT_NEAR(samples.back().raw_counts.y(), -1000.0, 1e-3);
  EXPECT_NEAR(samples.back().raw_counts.z(), 9000.0, 1e-3);
}

TEST(MavlinkSourceTest, ParametersReadByName) {
  FakeVehicle vehicle([](FrameWriter&, int) { return std::vector<std::vector<std::uint8_t>>{}; },
                      {{"INS_ACCOFFS_X", 0.25f}, {"INS_ACCSCAL_X", 1.01f}});
  Connection link(ParseLinkSpec(fmt::format("tcp:127.0.0.1:{}", vehicle.port()), "test"), {});
  ParamExchange quick;
  quick.round_s = 0.3;
  quick.rounds = 2;
  const ParamReadResult r = ReadParams(link, {"INS_ACCOFFS_X", "INS_ACCSCAL_X", "NO_SUCH_PARAM"}, quick);
  ASSERT_EQ(r.values.count("INS_ACCOFFS_X"), 1u);
  EXPECT_FLOAT_EQ(r.values.at("INS_ACCOFFS_X").value, 0.25f);
  EXPECT_FLOAT_EQ(r.values.at("INS_ACCSCAL_X").value, 1.01f);
  EXPECT_EQ(r.unanswered, std::vector<std::string>{"NO_SUCH_PARAM"});
}

std::vector<std::uint8_t> Raw(FrameWriter& w, double t_s, std::int16_t z_counts, std::uint8_t id) {
  Payload p(29, 0);  // time_usec, x, y, z acc, gyro, mag (int16), id (extension), temperature
  const auto t_us = static_cast<std::uint64_t>(t_s * 1e6);
  std::memcpy(p.data(), &t_us, 8);
  std::memcpy(p.data() + 12, &z_counts, 2);
  p[26] = id;
  return w.Encode(kRawImu, p);
}

Fixture ThreeImus() {
  Fixture f;
  for (const char* serial : {"ACC0", "ACC1", "ACC2"}) {
    FixtureSensor s;
    s.serial = serial;
    f.sensors.push_back(s);
  }
  return f;
}

// Issue 31: the IMUs of one vehicle on one link, as ArduPilot sends them (RAW_IMU of IMU 0,
// SCALED_IMU2), each its own sensor; IMU 2 never sends: it goes dead, named, the others stay up.
TEST(MavlinkSensorSetTest, EachImuInstanceItsOwnSensorAndADeadOneNamed) {
  FakeVehicle vehicle([](FrameWriter& w, int tick) {
    return std::vector<std::vector<std::uint8_t>>{Raw(w, 0.01 * tick, 4321, 0),
                                                  Scaled(w, kScaledImu2, 0.01 * tick, 1000)};
  });
  SourceOptions o = LinkOptions();
  o.dead_after_s = 1.0;
  SensorSetRequest request;
  request.fixture = ThreeImus();
  std::unique_ptr<SensorSetSource> set =
      OpenSensorSet(fmt::format("mavlink:tcp:127.0.0.1:{}", vehicle.port()), o, request);
  ASSERT_NE(dynamic_cast<MavlinkSensorSet*>(set.get()), nullptr);
  EXPECT_EQ(set->Describe(), fmt::format("mavlink:tcp:127.0.0.1:{} (IMUs 0-2: ACC0, ACC1, ACC2)", vehicle.port()));
  SensorSetSamples got;
  for (int i = 0; i < 400 && (set->status(0).samples_total < 20 || set->status(1).samples_total < 20 ||
                              set->status(2).link != LinkState::kDead);
       ++i)
    set->Read(0.05, &got);
  ASSERT_GE(got.per_sensor[0].size(), 20u);
  ASSERT_GE(got.per_sensor[1].size(), 20u);
  EXPECT_TRUE(got.per_sensor[2].empty());
  EXPECT_DOUBLE_EQ(got.per_sensor[0].back().raw_counts.z(), 4321.0);  // RAW_IMU: counts as sent
  EXPECT_NEAR(got.per_sensor[1].back().raw_counts.z(), 9806.65, 1e-6);  // SCALED_IMU2: 1000 mG
  EXPECT_EQ(set->status(0).link, LinkState::kUp);
  EXPECT_EQ(set->status(1).link, LinkState::kUp);
  EXPECT_DOUBLE_EQ(set->status(0).resolution_counts, 1.0);
  EXPECT_DOUBLE_EQ(set->status(1).resolution_counts, 9.80665);
  EXPECT_TRUE(Contains(set->status(1).last_notice, "no HIGHRES_IMU of IMU 1 came; reading SCALED_IMU2"))
      << set->status(1).last_notice;
  ASSERT_EQ(set->status(2).link, LinkState::kDead);
  EXPECT_TRUE(Contains(set->status(2).link_error, "arrive, but no HIGHRES_IMU, SCALED_IMU or RAW_IMU of IMU 2"))
      << set->status(2).link_error;
  for (std::size_t i = 1; i < got.per_sensor[0].size(); ++i)
    ASSERT_GT(got.per_sensor[0][i].t_s, got.per_sensor[0][i - 1].t_s);
}

// Each IMU of the set its own undo (its own INS_ACCnOFFS/SCAL): the vehicle sends the same
// corrected reading for IMUs 0, 1, 2; lane 0 is left as sent, lanes 1 and 2 each take back their
// own offset and scale, a_sensor = a_sent ./ scale + offset.
TEST(MavlinkSensorSetTest, EachImuTakesBackItsOwnCalibration) {
  FakeVehicle vehicle([](FrameWriter& w, int tick) {
    std::vector<std::vector<std::uint8_t>> out;
    for (std::uint8_t id = 0; id < 3; ++id) out.push_back(Highres(w, 0.01 * tick, {2.0, 1.0, -9.0}, id));
    return out;
  });
  SensorSetRequest request;
  request.fixture = ThreeImus();
  std::unique_ptr<SensorSetSource> set =
      OpenSensorSet(fmt::format("mavlink:tcp:127.0.0.1:{}", vehicle.port()), LinkOptions(), request);
  auto* imus = dynamic_cast<MavlinkSensorSet*>(set.get());
  ASSERT_NE(imus, nullptr);
  AccelUndo second;
  second.offset_mps2 = Eigen::Vector3d(0.1, -0.2, 0.3);
  second.scale = Eigen::Vector3d(2.0, 1.0, 0.5);
  AccelUndo third;
  third.offset_mps2 = Eigen::Vector3d(-0.5, 0.0, 0.0);
  imus->instances().SetUndo(1, second);
  imus->instances().SetUndo(2, third);
  EXPECT_FALSE(imus->instances().undo(0));
  SensorSetSamples got;
  for (int i = 0; i < 400 && (set->status(0).samples_total < 5 || set->status(1).samples_total < 5 ||
                              set->status(2).samples_total < 5);
       ++i)
    set->Read(0.05, &got);
  ASSERT_FALSE(got.per_sensor[0].empty());
  ASSERT_FALSE(got.per_sensor[1].empty());
  ASSERT_FALSE(got.per_sensor[2].empty());
  const Eigen::Vector3d sent(2000.0, 1000.0, -9000.0);  // counts of 0.001 m/s^2
  EXPECT_LT((got.per_sensor[0].back().raw_counts - sent).norm(), 1e-3);
  EXPECT_LT((got.per_sensor[1].back().raw_counts - Eigen::Vector3d(1100.0, 800.0, -17700.0)).norm(), 1e-3)
      << got.per_sensor[1].back().raw_counts.transpose();
  EXPECT_LT((got.per_sensor[2].back().raw_counts - Eigen::Vector3d(1500.0, 1000.0, -9000.0)).norm(), 1e-3)
      << got.per_sensor[2].back().raw_counts.transpose();
  EXPECT_TRUE(Contains(imus->DescribeReading(0), "own calibration: left in the readings"));
  EXPECT_TRUE(Contains(imus->DescribeReading(1), "own calibration undone"));
}

TEST(MavlinkSensorSetTest, OneVehicleHasAtMostThreeImusAndNoImuOfItsOwn) {
  SensorSetRequest three;
  three.fixture = ThreeImus();
  EXPECT_THROW(OpenSensorSet("mavlink:tcp:127.0.0.1:1,imu=1", SourceOptions{}, three), Error);
  SensorSetRequest four;
  four.sensors = 4;
  try {
    OpenSensorSet("mavlink:tcp:127.0.0.1:1", SourceOptions{}, four);
    ADD_FAILURE() << "4 IMUs on one vehicle taken";
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "at most 3 sensors on one MAVLink link")) << e.what();
  }
  SensorSetRequest columns;
  columns.sensors = 2;
  columns.columns = "t,ax,ay,az,ax,ay,az";
  EXPECT_THROW(OpenSensorSet("mavlink:tcp:127.0.0.1:1", SourceOptions{}, columns), Error);
}

TEST(MavlinkSpecTest, LinksAndOptions) {
  const MavlinkSourceSpec s = ParseMavlinkSpec("mavlink:udpout:[::1]:14555,imu=2,rate=200,msg=scaled,sys=3");
  EXPECT_EQ(s.link.kind, LinkKind::kUdpOut);
  EXPECT_EQ(s.link.host, "::1");
  EXPECT_EQ(s.imu, 2);
  EXPECT_EQ(*s.message, kScaledImu3);
  EXPECT_EQ(s.system, 3);
  EXPECT_EQ(s.Describe(), "mavlink:udpout:[::1]:14555,imu=2,rate=200,msg=scaled,sys=3");
  EXPECT_EQ(ParseMavlinkSpec("mavlink:serial:/dev/ttyACM0@57600").link.baud, 57600);
  for (const char* bad : {"mavlink:", "mavlink:tcp:host", "mavlink:udp:x:99999", "mavlink:ws:x:1",
                          "mavlink:tcp:h:1,imu=3", "mavlink:tcp:h:1,msg=fast", "mavlink:tcp:h:1,speed=2"})
    EXPECT_THROW(ParseMavlinkSpec(bad), Error) << bad;
}

}  // namespace
}  // namespace accelcal
