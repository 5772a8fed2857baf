// Record steps in the wizard engine (virtual bench at speed 0, memory journal): streamed in
// chunks, complete when the duration is covered, resumed after a kill with the gap recorded,
// a movement shown without stopping the record. Time is the samples' (and a test wall clock).
#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/source/sim_source.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/session/procedure.h"
#include "accelcal/session/session_journal.h"
#include "accelcal/app/wizard/wizard_engine.h"

namespace accelcal::wizard_record_test {
namespace {

constexpr double kRateHz = 100.0;  // the default scenario's

Procedure RecordProcedure(double duration_s, double chunk_s) {
  return ParseProcedure(
      "title = \"record test\"\n"
      "[sensor]\nnominal_scale_counts_per_mps2 = 34.8\nnominal_bias_counts = 2048\n"
      "[[step]]\nid = \"drift\"\nkind = \"record\"\ntitle = \"drift record\"\n"
      "up = [0, 0, 1]\npose = \"+z up\"\n"
      "duration_s = " + std::to_string(duration_s) + "\nchunk_s = " + std::to_string(chunk_s) + "\n",
      "test.toml");
}

SimOptions Fast(double bump_probability = 0.0) {
  SimOptions o;
  o.speed = 0.0;
  o.fast_chunk_s = 0.5;
  o.bump_probability = bump_probability;
  return o;
}

struct Rig {
  Rig(Procedure procedure, std::shared_ptr<SessionJournal> shared, double wall_s,
      SimOptions sim_options = Fast())
      : sim(sim::DefaultScenario(), sim_options), journal(std::move(shared)),
        engine(std::move(procedure), sim, *journal, Options(wall_s)) {}
  static WizardOptions Options(double wall_s) {
    WizardOptions o{"test", "op", "SN1", {}, 2.0, {}};
    o.wall_now_s = [wall_s] { return wall_s; };
    return o;
  }
  SimSource sim;
  std::shared_ptr<SessionJournal> journal;
  WizardEngine engine;
};

bool Busy(const WizardView& v) {
  return (v.screen == WizardScreen::kCapturing || v.screen == WizardScreen::kRecording) && !v.input;
}

// Accepts every question and polls while busy until `stop` or the end.
template <typename Stop>
void RunUntil(WizardEngine& e, Stop stop, int max_polls = 100000) {
  for (int i = 0; i < max_polls; ++i) {
    const WizardView v = e.View();
    if (v.finished || stop(v)) return;
    if (Busy(v)) {
      e.Poll(0.0);
    } else {
      e.Handle({IntentKind::kAccept, ""});
    }
  }
  FAIL() << "the wizard did not get there";
}

bool Never(const WizardView&) { return false; }

// The record's samples are whole: t increasing, at the source's rate inside every run.
void ExpectWholeRecord(const SessionJournal& journal, double duration_s) {
  const JournalRecord r = ReadRecord(journal, "drift");
  ASSERT_FALSE(r.samples.empty());
  const double span_s = r.samples.back().t_s - r.samples.front().t_s;
  EXPECT_GE(span_s, duration_s);
  EXPECT_LT(span_s, duration_s + 1.0 / kRateHz + 1e-9);
  size_t gap = 0;
  for (size_t i = 1; i < r.samples.size(); ++i) {
    const double dt = r.samples[i].t_s - r.samples[i - 1].t_s;
    if (gap < r.gaps.size() && r.samples[i - 1].t_s == r.gaps[gap].t_start_s) {
      EXPECT_EQ(r.samples[i].t_s, r.gaps[gap].t_end_s);
      ++gap;
      continue;
    }
    ASSERT_NEAR(dt, 1.0 / kRateHz, 1e-6) << "sample " << i;
  }
  EXPECT_EQ(gap, r.gaps.size()) << "every gap sits between two samples";
}

TEST(WizardRecordTest, ARecordStreamsInChunksAndCompletesAtItsDuration) {
  std::shared_ptr<SessionJournal> journal(MakeMemoryJournal());
  Rig rig(RecordProcedure(60.0, 10.0), journal, 1000.0);
  RunUntil(rig.engine, Never);
  EXPECT_TRUE(rig.engine.completed());
  EXPECT_TRUE(journal->Captures().empty());  // a record is chunks, not a capture
  const RecordSummary s = journal->RecordSummaryOf("drift");
  // 60 s at 100 Hz in chunks of 10 s: 6 whole chunks and the one sample that reaches 60 s.
  EXPECT_EQ(s.num_samples, 6001);
  EXPECT_EQ(s.num_chunks, 7);
  EXPECT_EQ(s.num_gaps, 0);
  ExpectWholeRecord(*journal, 60.0);
  ASSERT_EQ(journal->DoneSteps().count("drift"), 1u);
  EXPECT_EQ(journal->DoneSteps().at("drift").rfind("recorded 1 min 0 s over 1 min 0 s, 0 gaps", 0), 0u)
      << journal->DoneSteps().at("drift");
}

TEST(WizardRecordTest, TheViewShowsElapsedTimeAndTheDriftSeries) {
  std::shared_ptr<SessionJournal> journal(MakeMemoryJournal());
  Rig rig(RecordProcedure(600.0, 10.0), journal, 1000.0);
  RunUntil(rig.engine, [](const WizardView& v) { return v.record && v.record->elapsed_s >= 300.0; });
  const WizardView v = rig.engine.View();
  ASSERT_TRUE(v.record);
  EXPECT_EQ(v.screen, WizardScreen::kRecording);
  EXPECT_NEAR(v.progress, v.record->elapsed_s / 600.0, 1e-12);
  EXPECT_EQ(v.record->duration_s, 600.0);
  EXPECT_EQ(v.record->drift_bin_s, 3.0);  // 600 s over 200 points
  // Bins of 3 s up to the latest sample (the last one partly filled).
  EXPECT_EQ(v.record->drift.size(), static_cast<size_t>(std::floor(v.record->elapsed_s / 3.0 + 1e-9)) + 1);
  // The sim has no drift: each 3-s mean (300 samples) is within 6 sigma of the first minute's.
  for (const DriftPoint& p : v.record->drift)
    for (int a = 0; a < 3; ++a) EXPECT_LT(std::abs(p.drift_counts(a)), 6.0 * 1.7 / std::sqrt(300.0) + 0.5);
  // The live Allan curve: the default bench's white noise (1.5, 1.5, 1.7 counts, plus the
  // rounding's 1/12 count^2) at the first tau, one sample, where AVAR = sigma^2; taus up to a
  // quarter of the record.
  const double sigma[3] = {1.5, 1.5, 1.7};
  for (size_t a = 0; a < 3; ++a) {
    const std::vector<AllanCurvePoint>& curve = v.record->allan[a];
    ASSERT_GT(curve.size(), 10u) << a;
    EXPECT_NEAR(curve.front().tau_s, 0.01, 1e-9);
    const double white = std::sqrt(sigma[a] * sigma[a] + 1.0 / 12.0);
    EXPECT_NEAR(curve.front().adev_counts, white, 0.05 * white) << a;
    for (size_t i = 1; i < curve.size(); ++i) EXPECT_GT(curve[i].tau_s, curve[i - 1].tau_s);
    EXPECT_LE(curve.back().tau_s, v.record->elapsed_s / 4.0 + 0.01);
  }
  EXPECT_NE(v.prompt.find("00:05:00 of 00:10:00"), std::string::npos) << v.prompt;
}

TEST(WizardRecordTest, AKilledRecordResumesWithTheGapRecorded) {
  std::shared_ptr<SessionJournal> journal(MakeMemoryJournal());
  {
    Rig first(RecordProcedure(120.0, 10.0), journal, 1000.0);
    RunUntil(first.engine, [](const WizardView& v) { return v.record && v.record->elapsed_s >= 45.0; });
  }  // dies here, as by kill -9: the chunk being filled is lost
  const RecordSummary before = journal->RecordSummaryOf("drift");
  ASSERT_GE(before.num_chunks, 4);
  ASSERT_EQ(journal->DoneSteps().count("drift"), 0u);
  const JournalRecord kept = ReadRecord(*journal, "drift");

  Rig second(RecordProcedure(120.0, 10.0), journal, 1042.0);
  WizardView v = second.engine.View();
  EXPECT_TRUE(v.resumed);
  // The noise floor is measured again first (the operator says when the sensor rests).
  RunUntil(second.engine, [](const WizardView& w) {
    return w.screen == WizardScreen::kPlacePose && w.prompt.rfind("Noise floor", 0) != 0;
  });
  EXPECT_EQ(second.engine.View().prompt.rfind("Resuming the drift record: 40 s recorded", 0), 0u)
      << second.engine.View().prompt;
  RunUntil(second.engine, [](const WizardView& w) { return w.record && w.record->gaps == 1; });
  EXPECT_NE(second.engine.View().prompt.find("gap of 42 s"), std::string::npos) << second.engine.View().prompt;
  RunUntil(second.engine, Never);
  EXPECT_TRUE(second.engine.completed());

  const JournalRecord r = ReadRecord(*journal, "drift");
  ASSERT_EQ(r.gaps.size(), 1u);
  // The gap runs from the last sample stored to the first after the resume: 42 s of the wall
  // clock (1000 -> 1042) since the last chunk was committed.
  EXPECT_EQ(r.gaps[0].t_start_s, before.t_last_s);
  EXPECT_NEAR(r.gaps[0].duration_s(), 42.0, 1e-9);
  EXPECT_EQ(r.gaps[0].reason, "resumed after interruption");
  // What was committed before the kill is unchanged, and the rest follows it.
  ASSERT_GT(r.samples.size(), kept.samples.size());
  for (size_t i = 0; i < kept.samples.size(); ++i) ASSERT_EQ(r.samples[i].t_s, kept.samples[i].t_s);
  ExpectWholeRecord(*journal, 120.0);
  const RecordSummary after = journal->RecordSummaryOf("drift");
  EXPECT_NEAR(after.recorded_s() + after.gaps_s, after.span_s(), 1e-9);
  EXPECT_NE(journal->DoneSteps().at("drift").find("1 gap (42 s)"), std::string::npos)
      << journal->DoneSteps().at("drift");
}

TEST(WizardRecordTest, QuitCommitsTheChunkBeingFilled) {
  std::shared_ptr<SessionJournal> journal(MakeMemoryJournal());
  Rig rig(RecordProcedure(120.0, 10.0), journal, 1000.0);
  RunUntil(rig.engine, [](const WizardView& v) { return v.record && v.record->elapsed_s >= 25.0; });
  const long samples = rig.engine.View().record->samples;
  rig.engine.Handle({IntentKind::kQuit, ""});
  EXPECT_EQ(journal->RecordSummaryOf("drift").num_samples, samples);
  EXPECT_FALSE(rig.engine.completed());
}

TEST(WizardRecordTest, AMovementIsShownAndTheRecordGoesOn) {
  std::shared_ptr<SessionJournal> journal(MakeMemoryJournal());
  // Every placement is followed by a knock 1-4 s after the sensor settles: inside the record.
  Rig rig(RecordProcedure(30.0, 10.0), journal, 1000.0, Fast(1.0));
  RunUntil(rig.engine, [](const WizardView& v) { return v.record && v.record->bumps > 0; });
  const WizardView v = rig.engine.View();
  ASSERT_EQ(rig.sim.bumps_scheduled(), 1);
  EXPECT_EQ(v.record->bumps, 1);
  EXPECT_NE(v.stability_text.find("the record goes on"), std::string::npos) << v.stability_text;
  EXPECT_TRUE(v.problem.empty());
  RunUntil(rig.engine, Never);
  EXPECT_TRUE(rig.engine.completed());
  EXPECT_NE(journal->DoneSteps().at("drift").find("1 movement"), std::string::npos);
}

TEST(WizardRecordTest, NoMovementIsSeenInAQuietRecord) {
  std::shared_ptr<SessionJournal> journal(MakeMemoryJournal());
  Rig rig(RecordProcedure(300.0, 10.0), journal, 1000.0);
  RunUntil(rig.engine, Never);
  EXPECT_NE(journal->DoneSteps().at("drift").find("0 movements"), std::string::npos)
      << journal->DoneSteps().at("drift");
}

TEST(WizardRecordTest, BackKeepsAFinishedRecordAndReturnsToASkippedOne) {
  Procedure p = RecordProcedure(20.0, 10.0);
  ProcedureStep second = p.steps.front();
  second.id = "drift2";
  p.steps.push_back(second);
  std::shared_ptr<SessionJournal> journal(MakeMemoryJournal());
  Rig rig(p, journal, 1000.0);
  RunUntil(rig.engine, [](const WizardView& v) { return v.step_index == 3; });  // at drift2
  rig.engine.Handle({IntentKind::kBack, ""});
  EXPECT_EQ(rig.engine.View().step_index, 3);
  EXPECT_NE(rig.engine.View().problem.find("nothing to go back to"), std::string::npos);
  EXPECT_EQ(journal->RecordSummaryOf("drift").num_samples, 2001);  // untouched
}

}  // namespace
}  // namespace accelcal::wizard_record_test
