// A capture starts from the samples taken after the answer (issue 27, item 6): what a live link
// delivered while a question waited is read and dropped; the virtual bench is left alone.
#include <fcntl.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/source/discard_backlog.h"
#include "accelcal/acquire/source/sim_source.h"
#include "accelcal/acquire/source/source_spec.h"
#include "source_test_support.h"

namespace accelcal {
namespace {

using testing::ReadUntil;
using testing::SampleLines;
using testing::WriteAll;

TEST(DiscardBacklog, WhatArrivedBeforeIsDroppedWhatComesAfterIsRead) {
  int fds[2];
  ASSERT_EQ(pipe2(fds, O_CLOEXEC), 0);
  SourceOptions options;
  options.stdin_fd = fds[0];
  const std::unique_ptr<SampleSource> source = OpenSource("-", options);
  // 3 s of samples waited in the pipe while the question was on the screen (the old pose) ...
  ASSERT_TRUE(WriteAll(fds[1], SampleLines(0, 300)));
  EXPECT_EQ(DiscardBacklog(*source), 300);
  // ... then the answer: only what comes after it is read.
  ASSERT_TRUE(WriteAll(fds[1], SampleLines(300, 50)));
  std::vector<Sample> after;
  ASSERT_TRUE(ReadUntil(*source, &after, [&](const SourceStatus&) { return after.size() >= 50; }));
  ASSERT_EQ(after.size(), 50u);
  EXPECT_EQ(after.front().raw_counts.x(), 300.0);
  EXPECT_EQ(DiscardBacklog(*source), 0);  // nothing waiting: nothing dropped, no wait
  ::close(fds[1]);
  ::close(fds[0]);
}

TEST(DiscardBacklog, TheVirtualBenchIsLeftAlone) {
  SimOptions o;
  o.speed = 0.0;
  SimSource sim(sim::DefaultScenario(), o);
  EXPECT_EQ(DiscardBacklog(sim), 0);
}

}  // namespace
}  // namespace accelcal
