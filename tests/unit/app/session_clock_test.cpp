// One session clock across resumes: a resumed run's samples come after the session's last one,
// by the gap on the computer's clock, and the shift is recorded.
#include "accelcal/app/wizard/session_clock.h"

#include <gtest/gtest.h>

#include "test_support.h"

namespace accelcal {
namespace {

std::vector<Sample> Chunk(double t0_s, int n) {
  std::vector<Sample> out(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) out[static_cast<size_t>(k)].t_s = t0_s + 0.01 * k;
  return out;
}

Capture Ending(double t_last_s) {
  Capture c;
  c.id = 1;
  c.samples = Chunk(t_last_s - 0.99, 100);
  return c;
}

TEST(SessionClock, AFirstRunKeepsTheSourcesClock) {
  std::unique_ptr<SessionJournal> journal = MakeMemoryJournal();
  SessionModel model(*journal);
  SessionClock clock(model, [] { return 1000.0; });
  std::vector<Sample> chunk = Chunk(0.0, 10);
  clock.Shift(&chunk, model);
  EXPECT_DOUBLE_EQ(chunk.front().t_s, 0.0);
  EXPECT_TRUE(clock.note().empty());
}

// Issue 12, problem 5: each run restarted the sample clock.
TEST(SessionClock, AResumedRunGoesOnAfterTheLastCaptureByTheGap) {
  std::unique_ptr<SessionJournal> journal = MakeMemoryJournal();
  double wall_s = 5000.0;
  {
    SessionModel model(*journal);
    model.RecordCapture("pose_pz", Ending(1017.21));
    SessionClock clock(model, [&] { return wall_s; });
    clock.MarkCapture(1017.21, model);
  }
  wall_s += 42.0;  // the program was down 42 s
  SessionModel model(*journal);
  SessionClock clock(model, [&] { return wall_s; });
  std::vector<Sample> chunk = Chunk(13.56, 10);  // the source restarted
  clock.Shift(&chunk, model);
  EXPECT_NEAR(chunk.front().t_s, 1017.21 + 42.0, 1e-9);
  EXPECT_NEAR(chunk[1].t_s - chunk[0].t_s, 0.01, 1e-9);
  std::vector<Sample> next = Chunk(13.66, 1);
  clock.Shift(&next, model);
  EXPECT_NEAR(next.front().t_s, 1017.21 + 42.0 + 0.1, 1e-9);
  EXPECT_TRUE(testing::Contains(clock.note(), "42.0 s after the last sample")) << clock.note();
  EXPECT_TRUE(testing::Contains(model.inputs().at(SessionClock::kClockStep).at("resume 1"), "gap of 42.000 s"));
  // What the record says the run's first sample became: the source's t plus the offset.
  const std::optional<double> at_s =
      SessionClock::ResumedAtS(model.inputs().at(SessionClock::kClockStep).at("resume 1"));
  ASSERT_TRUE(at_s.has_value());
  EXPECT_NEAR(*at_s - 13.56, clock.offset_s(), 1e-6);
  EXPECT_FALSE(SessionClock::ResumedAtS("gap of 42 s").has_value());
}

TEST(SessionClock, ASourceWhoseClockRunsOnIsLeftAlone) {
  std::unique_ptr<SessionJournal> journal = MakeMemoryJournal();
  {
    SessionModel model(*journal);
    model.RecordCapture("pose_pz", Ending(100.0));
  }
  SessionModel model(*journal);
  SessionClock clock(model, [] { return 0.0; });
  std::vector<Sample> chunk = Chunk(5000.0, 3);
  clock.Shift(&chunk, model);
  EXPECT_DOUBLE_EQ(chunk.front().t_s, 5000.0);
}

}  // namespace
}  // namespace accelcal
