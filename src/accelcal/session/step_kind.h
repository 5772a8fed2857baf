// The kinds of step a procedure is made of, and what each kind is: one table (step_kind.cpp)
// that every question "does this step capture? keep a record? may it be skipped? which fields
// does it read from the procedure file?" is answered from. The wizard's controller of each kind
// (app/wizard/steps/) does the rest; ARCHITECTURE.md, "How to add a step kind", says where.
//
// A kind may also be added at run time (RegisterStepKind: a kind defined beside its wizard
// controller, registered at the program's start by app/wizard/step_registry.h's
// RegisterStepKinds, or one a test defines); such kinds take the values after the built-in ones
// and are known to every layer that reads a procedure once registered.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace accelcal {

struct ProcedureStep;

enum class StepKind : int {
  kLevel,      // level the table (reversal method)
  kStatic,     // a static pose on the prism
  kTurntable,  // a turntable run
  kRecord,     // a long static record (noise, drift), streamed to the journal in chunks
  kFit,        // the nine-parameter fit over the accepted captures
  kDiagnosis,  // the diagnosis; asks before adopting an effect
  kReport,     // the calibration report; the session's result is recorded
  kAnalysis,   // the noise or drift analysis of an earlier record step, shown
};

// What a step takes from the sensor.
enum class StepAcquires {
  kNothing,           // it computes or asks (fit, diagnosis, report, analysis)
  kReadings,          // readings it uses itself and does not keep (the leveling's two)
  kStaticCapture,     // one capture of a prism pose, kept for the fit
  kTurntableCapture,  // one capture of a turntable run, kept for the fit
  kRecord,            // a long record, kept in chunks
};

// The capture defaults of the procedure file's [checks], which a step's fields fall back on.
struct StepDefaults {
  double duration_s = 10.0;  // capture_duration_s
  double timeout_s = 60.0;   // capture_timeout_s
};

// Which values a number may take.
enum class FieldRange { kAny, kNonNegative, kPositive };

// One step's fields as the procedure file gives them (io/procedure_file.cpp reads TOML through
// it). A missing key takes `fallback`, or is an error when there is none; every failure throws
// accelcal::InputError pointing at the offending text.
class StepFields {
 public:
  virtual ~StepFields() = default;
  virtual bool Has(std::string_view key) const = 0;
  virtual double Number(std::string_view key, std::optional<double> fallback,
                        FieldRange range = FieldRange::kAny) = 0;
  virtual std::string Text(std::string_view key, std::optional<std::string> fallback) = 0;
  virtual Eigen::Vector3d Vector3(std::string_view key, std::optional<Eigen::Vector3d> fallback) = 0;
  // Throws at `key`'s value, or at the step when the key is absent.
  [[noreturn]] virtual void Fail(std::string_view key, const std::string& message) const = 0;
};

// A kind's own fields when ProcedureStep has no member that fits them: its reader makes them
// (ProcedureStep::own_fields, a type of the kind's own derived from this), its controller reads
// them back.
struct StepOwnFields {
  virtual ~StepOwnFields() = default;
};

struct StepKindInfo {
  std::string_view name;  // in the procedure file; must outlive the table (a literal)
  StepAcquires acquires = StepAcquires::kNothing;
  bool skippable = true;   // s may skip it (the fit and the report may not be skipped)
  bool calibrates = false;  // it records the session's calibration (the report)
  // Every step of the kind takes this pose (the leveling: "+z up", the reversal's); empty: the
  // step's own. The title defaults to the step's own pose, else to the kind's name.
  std::string_view fixed_pose;
  // Reads the kind's own fields of `step` (nullptr: it has none).
  void (*read_fields)(StepFields& fields, ProcedureStep& step, const StepDefaults& defaults) = nullptr;
  // Checks `step` against the steps before it and may complete it from them (a repeat of an
  // earlier pose takes that pose); nullptr: nothing to check.
  void (*check_order)(ProcedureStep& step, const std::vector<ProcedureStep>& earlier,
                      StepFields& fields) = nullptr;
};

// The kind's row; throws accelcal::Error for a value that is no kind.
const StepKindInfo& InfoOf(StepKind kind);
// "level", "static", "turntable", "record", "fit", "diagnosis", "report", "analysis",
// "write_back", or a registered kind's name; "?" for a value that is no kind.
std::string_view StepKindToString(StepKind kind);
std::optional<StepKind> StringToStepKind(std::string_view text);
// Every kind's name, the table's order then the registered ones'.
std::vector<std::string_view> StepKindNames();
// Adds a kind; returns its value. Registering the same name again returns the kind it has (the
// row is not replaced). Not thread-safe: register before the kinds are used.
StepKind RegisterStepKind(const StepKindInfo& info);

// The questions every part of the program asks of a step's kind, answered from the table:
// it takes readings from the sensor (the noise floor is measured before its first one);
bool UsesSensor(StepKind kind);
// it keeps one accepted capture for the fit (left out when a lowered noise floor fails it, taken
// again on the way back, a gap of the session while it has none);
bool KeepsCapture(StepKind kind);
// it keeps what it acquires (a capture or a record): the way back returns to it when it has none;
bool KeepsData(StepKind kind);
// it keeps a long record (the noise and drift analyses read it);
bool IsRecordStep(StepKind kind);
// its capture is a pose of the prism (a tilted one is a known pose to the orientation check).
bool IsStaticPoseStep(StepKind kind);
// its capture is a turntable run (a list names it with the radius and speed it was taken at).
bool IsTurntableRunStep(StepKind kind);

}  // namespace accelcal
