// The write-back (kind "write_back", after the report; issue 30, docs/devices.md): the
// calibration the report recorded, offered to the MAVLink vehicle the session read, while it is
// still on the link. The step first shows what it would send (the PARAM_SETs of the vehicle's
// offsets and scales, as `accelcal export-cal --to mavlink:` computes them, with what the
// autopilot's model cannot carry) and asks; nothing is written without a typed "yes" (Enter,
// as `yes ''` answers, leaves the vehicle as it is). On yes: the values before are read, each
// PARAM_SET sent and its echo awaited, every value read back and compared
// (app/device/vehicle_writeback.h); the outcome is shown and recorded, and a write that stopped
// says which parameters were written and which not (r tries again). A source that is no MAVLink
// vehicle, or a session whose vehicle calibration was left in the readings, has nothing to write:
// the step says so and goes on; a session of a vehicle's several IMUs writes each at its end
// (WizardOptions::write_back_elsewhere says so).
#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "accelcal/acquire/mavlink/mavlink_source.h"
#include "accelcal/app/device/vehicle_writeback.h"
#include "accelcal/app/wizard/step_registry.h"
#include "accelcal/app/wizard/steps/result_step.h"
#include "accelcal/base/error.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/session/session_inputs.h"

namespace accelcal {
namespace {

constexpr const char* kWriteBackAnswerKey = "write_back";

std::string Lowered(const std::string& text) {
  std::string out;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string Joined(const std::vector<std::string>& lines) { return fmt::format("{}", fmt::join(lines, "\n")); }

class WriteBackStep final : public ResultStep {
 public:
  using ResultStep::ResultStep;

  void AddText(std::vector<std::string>& lines) const override {
    ResultStep::AddText(lines);
    lines.insert(lines.end(), outcome_lines_.begin(), outcome_lines_.end());
  }

  void SetView(WizardView& v) const override {
    if (phase_ != Phase::kStopped) return ResultStep::SetView(v);
    v.screen = WizardScreen::kReport;
    v.prompt = "The vehicle was not fully written: the lines above say what it holds now.";
    v.keys = WithNavigation({{"Enter", "leave it so"}, {"r", "try again"}});
  }

 protected:
  StepOutcome Run() override;

  void Answer(const Intent& intent, bool accept) override {
    if (phase_ != Phase::kAsk) {
      // A plan that could not be made (a problem on screen) waits for r, s or b.
      const bool blocked = phase_ == Phase::kNothingToWrite && !session_.screen.problem.empty();
      if (accept && !blocked) session_.sequence.FinishStep(FinishedOutcome());
      return;
    }
    const std::string answer = intent.kind == IntentKind::kSubmitText ? Lowered(intent.text) : "";
    if (answer == "yes") return Write();
    if (answer.empty() || answer == "no" || answer == "n") return session_.sequence.FinishStep("declined");
    input_error_ = "type yes to write the values into the vehicle, or no (or just Enter) to leave it as it is";
  }

  void SetAnswerView(WizardView& v) const override {
    switch (phase_) {
      case Phase::kNothingToWrite:
        v.prompt = "Nothing to write into a vehicle; press Enter to finish.";
        v.keys = WithNavigation({{"Enter", "continue"}});
        return;
      case Phase::kAsk:
        v.screen = WizardScreen::kInput;
        v.prompt = "Write this calibration into the vehicle? Nothing is written without your yes.";
        v.input = InputRequest{kWriteBackAnswerKey,
                               "Type yes to write these values into the vehicle (each one echoed, then all "
                               "read back), or no to leave it as it is",
                               "no", input_error_};
        v.keys = WithNavigation({{"Enter", "answer"}});
        return;
      case Phase::kWritten:
      case Phase::kStopped:
        v.prompt = "The vehicle holds the new calibration; press Enter to finish.";
        v.keys = WithNavigation({{"Enter", "continue"}});
        return;
    }
  }

 private:
  enum class Phase { kNothingToWrite, kAsk, kWritten, kStopped };

  // The calibration recorded by the report, planned as the vehicle's parameters.
  StepOutcome Plan(MavlinkSource& vehicle);
  void Write();
  std::string FinishedOutcome() const {
    switch (phase_) {
      case Phase::kWritten: return "written";
      case Phase::kStopped: return "stopped: " + stopped_;
      default: return "nothing to write";
    }
  }

  Phase phase_ = Phase::kNothingToWrite;
  WritebackPlan plan_;
  std::string input_error_;
  std::vector<std::string> outcome_lines_;  // what the write did, under the plan
  std::string stopped_;                     // why it stopped, when it did
};

StepOutcome WriteBackStep::Run() {
  phase_ = Phase::kNothingToWrite;
  input_error_.clear();
  outcome_lines_.clear();
  stopped_.clear();
  MavlinkSource* vehicle = session_.options.vehicle;
  if (vehicle == nullptr && !session_.options.write_back_elsewhere.empty())
    return {{session_.options.write_back_elsewhere}, {}, "", ""};
  if (vehicle == nullptr)
    return {{"The source is not a MAVLink vehicle: there is no vehicle to write the calibration into.",
             "To load it elsewhere: accelcal export-cal SESSION --to ardupilot, px4, c-header, ..."},
            {}, "", ""};
  if (!vehicle->undo())
    return {{"The vehicle's own calibration was left in the readings (--vehicle-calibration as-is): this "
             "calibration describes the sensor after it, so written as the vehicle's own offsets and "
             "scales it would be wrong. Nothing is offered.",
             "To write one: reset the vehicle's calibration (accelcal device-info --source ... --reset "
             "--apply) or let the wizard take it out, and calibrate again."},
            {}, "", ""};
  try {
    return Plan(*vehicle);
  } catch (const Error& e) {
    return {{}, {}, fmt::format("the calibration cannot be written into the vehicle: {}", e.what()),
            "s skips this step; accelcal export-cal SESSION --to mavlink:... --apply tries again later"};
  }
}

StepOutcome WriteBackStep::Plan(MavlinkSource& vehicle) {
  const std::optional<std::string> result = session_.model.Result();
  if (!result)
    return {{}, {}, "no calibration is recorded in the session: the report step has not recorded one",
            "b goes back to it"};
  const Calibration cal = CalibrationFromJsonText(*result, session_.options.session_name);
  DriverScaleOptions driver;
  if (std::optional<DriverScaleOptions> of_unit = DriverScaleOfUnit(cal.reading_unit)) {
    driver = *of_unit;
  } else {  // counts (RAW_IMU): the procedure's datasheet scaling, as export-cal --procedure
    driver.nominal_scale_counts_per_mps2 = session_.procedure.nominal.scale_counts_per_mps2;
    driver.nominal_bias_counts = session_.procedure.nominal.bias_counts;
  }
  mavlink::Connection& link = vehicle.connection();
  plan_ = PlanWriteback(cal, StackOf(link.vehicle().autopilot), vehicle.spec().imu, driver);
  StepOutcome out;
  out.lines.push_back(fmt::format("{} on {}, IMU {}: the {} accelerometer parameters this calibration gives",
                                  link.vehicle().Describe(), link.LinkName(), plan_.imu, StackName(plan_.stack)));
  const std::vector<std::string> writes = DescribeWrites(plan_.writes);
  for (const std::string& w : writes) out.lines.push_back("  " + w);
  for (const std::string& s : plan_.cannot_hold) out.lines.push_back("cannot hold: " + s);
  for (const std::string& s : plan_.notes) out.lines.push_back("note: " + s);
  session_.model.RecordInput(step_.id, write_back_key::kPlanned, Joined(writes));
  phase_ = Phase::kAsk;
  return out;
}

void WriteBackStep::Write() {
  input_error_.clear();
  WritebackOutcome outcome;
  try {
    outcome = ApplyWrites(session_.options.vehicle->connection(), plan_.stack, plan_.writes);
  } catch (const Error& e) {
    outcome.failed = e.what();
    for (const ParamWrite& w : plan_.writes) outcome.not_sent.push_back(w.name);
  }
  outcome_lines_ = outcome.Lines();
  session_.model.RecordInput(step_.id, write_back_key::kOutcome, Joined(outcome_lines_));
  if (outcome.ok()) {
    phase_ = Phase::kWritten;
    outcome_lines_.push_back("Written: every value was echoed and read back as sent. Reboot the vehicle "
                             "before it flies, as after any calibration.");
    return;
  }
  phase_ = Phase::kStopped;
  stopped_ = outcome.failed.empty() ? outcome.reread_mismatches.front() : outcome.failed;
  session_.screen.problem = "the write-back stopped: " + stopped_;
  session_.screen.hint = "r tries again; Enter leaves the vehicle as the lines say (the values before are "
                         "listed, to go back to)";
}

std::string WriteBackInputHelp(std::string_view key) {
  if (key != kWriteBackAnswerKey) return "";
  return "Type yes to write the listed values into the vehicle's parameters: each PARAM_SET is sent and "
         "its echo awaited, then every value is read back and compared. Anything else (no, or an empty "
         "answer) leaves the vehicle as it is; accelcal export-cal SESSION --to mavlink:... --apply "
         "writes them later.";
}

// A write-back writes the calibration an earlier report step recorded.
void CheckWriteBackOrder(ProcedureStep&, const std::vector<ProcedureStep>& earlier, StepFields& f) {
  const bool earlier_report = std::any_of(earlier.begin(), earlier.end(),
                                          [](const ProcedureStep& e) { return InfoOf(e.kind).calibrates; });
  if (!earlier_report)
    f.Fail("kind", "a write_back step comes after the report step: it writes the calibration the report records");
}

}  // namespace

// The report's calibration offered to the MAVLink vehicle read, written on a yes.
StepKindDefinition WriteBackStepKind() {
  return {{"write_back", StepAcquires::kNothing, true, false, "", nullptr, &CheckWriteBackOrder},
          {StepKind{}, &MakeStepController<WriteBackStep>, &ResultEstimateS, nullptr, &WriteBackInputHelp}};
}

}  // namespace accelcal
