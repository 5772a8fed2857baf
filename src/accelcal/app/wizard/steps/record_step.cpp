// A long record (kind "record": the noise and drift records), streamed to the journal in chunks
// by RecordStepWriter (record_step_writer.h): never refused for drift, a movement is shown and
// the record goes on; q commits the chunk being filled. An interrupted record resumes where it
// stopped (without placing the sensor again) and its gap is recorded; a silent link stops it,
// kept up to its last sample (Enter goes on). The step is done (its outcome: the recorded and gap
// times) when its duration is covered.
#include <algorithm>
#include <memory>

#include <fmt/core.h>

#include "accelcal/app/wizard/record_step_writer.h"
#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/app/wizard/steps/acquiring_step.h"
#include "accelcal/base/duration_text.h"

namespace accelcal {
namespace {

class RecordStep final : public AcquiringStep {
 public:
  using AcquiringStep::AcquiringStep;

  bool Acquiring() const override { return phase_ == Phase::kOwn || AcquiringStep::Acquiring(); }

  void OnAcquisition(AcquisitionEvent event) override {
    if (event == AcquisitionEvent::kRecordComplete) return Finish();
    if (event == AcquisitionEvent::kRecordSilent) {
      // Stopped, the chunk being filled committed: Enter resumes it (with the gap stated).
      session_.screen.problem = session_.acq.reason();
      session_.screen.hint = "check the cable or the sample server; Enter goes on with the record, q leaves "
                             "(what was recorded is in the session)";
      phase_ = Phase::kProblem;
      return;
    }
    AcquiringStep::OnAcquisition(event);
  }

  bool BackWithin() override {
    if (phase_ != Phase::kOwn) return AcquiringStep::BackWithin();
    EnterPlace();  // a finished record is kept; a running one keeps its chunks
    return true;
  }

  void KeepAfterSkipDeclined() override { EnterPlace(); }

  double WaitingCaptureS(bool) const override { return kNaN; }

 protected:
  // The operator says the sensor is in place (on the sim, this places it). A record resumed after
  // an interruption assumes the sensor was left where it was: it is not placed again.
  void BeginCapture() override {
    if (!Resumable()) PlaceOnBench();
    Start();
  }

  void OnCaptureAccepted(Capture) override {}  // a record takes no capture

  void SetPlaceView(WizardView& v) const override {
    v.screen = WizardScreen::kPlacePose;
    if (Resumable()) {
      const RecordSummary r = session_.model.RecordSummaryOf(step_.id);
      v.prompt = fmt::format("Resuming the {}: {} recorded of {}. Leave the sensor as it is and "
                             "press Enter to go on recording (the gap is recorded).",
                             step_.title, FormatLongDuration(r.recorded_s()), FormatLongDuration(step_.duration_s));
      v.keys = WithNavigation({{"Enter", "resume"}});
      return;
    }
    v.prompt = fmt::format("Put the prism on the table with {} and let go; press Enter to start the {} record.",
                           step_.pose_name, FormatLongDuration(step_.duration_s));
    v.keys = WithNavigation({{"Enter", "capture"}});
  }

  // The record running: its clock, its movements, its drift and Allan curves; the time left is
  // the record's and the steps' after it.
  void SetOwnView(WizardView& v) const override {
    v.screen = WizardScreen::kRecording;
    v.keys = {{"s", "skip"}, {"b", "back"}, {"q", "save and quit"}};
    const RecordStepWriter& record = session_.acq.record();
    const RecordView r = record.View();
    v.progress = std::clamp(r.elapsed_s / r.duration_s, 0.0, 1.0);
    const std::string clock = fmt::format("{} of {}", FormatClock(r.elapsed_s), FormatClock(r.duration_s));
    if (session_.acq.record_settling()) {
      v.prompt = fmt::format("Recording the {} with {}; letting the sensor settle", step_.title, step_.pose_name);
    } else if (record.resuming()) {
      const std::string gap = r.gaps > record.resumed_from().num_gaps
                                  ? fmt::format("gap of {:.0f} s", r.gaps_s - record.resumed_from().gaps_s)
                                  : "waiting for the first sample";
      v.prompt = fmt::format("Resuming the {}: {} recorded, {}; recording {}", step_.title,
                             FormatLongDuration(record.resumed_from().recorded_s()), gap, clock);
    } else {
      v.prompt = fmt::format("Recording the {} with {}; {}", step_.title, step_.pose_name, clock);
    }
    v.stability_text = r.bumps == 0 ? "still"
                                    : fmt::format("moved {} time{} (last {}); the record goes on", r.bumps,
                                                  r.bumps == 1 ? "" : "s", r.last_bump);
    v.record = r;
    v.session_left_s = std::max(r.duration_s - r.elapsed_s, 0.0) + session_.sequence.SessionLeftS(true);
    v.time_text = WaitingTimeText(kNaN, kNaN, v.session_left_s);
  }

 private:
  bool Resumable() const { return session_.model.RecordSummaryOf(step_.id).num_chunks > 0; }

  // How long a record waits on a silent link (connected, sending nothing readable) before it
  // stops: the slack its procedure gives beyond the record's own length (timeout_s - duration_s:
  // the procedure's capture_timeout_s, 60 s, unless the step sets timeout_s), at least 1 s.
  double SilenceTimeoutS() const { return std::max(1.0, step_.timeout_s - step_.duration_s); }

  void Start() {
    RecordStepWriterOptions o;
    o.duration_s = step_.duration_s;
    o.chunk_s = step_.chunk_s;
    o.noise_std_counts = session_.noise_floor.floor()->std_counts;
    o.wall_now_s = session_.options.wall_now_s;
    // A fresh placement lets the hand go first; a resumed record goes on at once.
    const bool settle = !Resumable();
    session_.acq.StartRecord(std::make_unique<RecordStepWriter>(session_.model, step_.id, o), settle, SteadyNowS(),
                             SilenceTimeoutS());
    session_.screen.problem.clear();
    session_.screen.hint.clear();
    phase_ = Phase::kOwn;
    // Killed after the last chunk but before the step was marked done: nothing left to record.
    if (session_.acq.record().complete()) Finish();
  }

  void Finish() {
    const std::string outcome = session_.acq.record().Outcome();
    session_.acq.Stop();
    session_.sequence.FinishStep(outcome);
  }
};

}  // namespace

StepControllerKind RecordStepKind() {
  return {StepKind::kRecord, &MakeStepController<RecordStep>, &PlacedStepEstimateS, nullptr, nullptr};
}

}  // namespace accelcal
