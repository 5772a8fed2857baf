#include "accelcal/app/wizard/calibration_steps.h"

#include <algorithm>
#include <sstream>

#include <fmt/format.h>

#include "accelcal/app/analyze_recording.h"
#include "accelcal/app/wizard/diagnosis_words.h"
#include "accelcal/app/wizard/fit_words.h"
#include "accelcal/app/wizard/next_steps.h"
#include "accelcal/app/wizard/session_gaps.h"
#include "accelcal/analysis/noise_analysis.h"
#include "accelcal/app/noise_records.h"
#include "accelcal/base/error.h"
#include "accelcal/io/session_result_file.h"
#include "accelcal/report/allan_text.h"
#include "accelcal/report/fit_text.h"
#include "accelcal/report/noise_text.h"
#include "accelcal/report/report_model.h"

namespace accelcal {
namespace {

// `text` in lines of at most `width` columns, broken at blanks; its leading blanks kept, the
// lines after the first indented two more.
std::vector<std::string> WrapWords(const std::string& text, size_t width) {
  const size_t indent = std::min(text.find_first_not_of(' '), text.size());
  std::vector<std::string> out;
  std::string line(indent, ' ');
  bool has_word = false;
  std::istringstream words(text);
  for (std::string w; words >> w;) {
    if (has_word && line.size() + 1 + w.size() > width) {
      out.push_back(line);
      line = std::string(indent + 2, ' ');
      has_word = false;
    }
    line += (has_word ? " " : "") + w;
    has_word = true;
  }
  if (has_word) out.push_back(line);
  return out;
}

std::vector<std::string> SplitLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::string Figures(const RecordAnalysis& a, double AllanReadOffs::*figure) {
  std::string out;
  for (size_t i = 0; i < 3; ++i) {
    const std::optional<AllanReadOffs>& r = a.axes[i].read_offs;
    const double v = r ? (*r).*figure : kNaN;
    out += fmt::format(" {} {}", "xyz"[i], std::isfinite(v) ? fmt::format("{:.4g}", v) : "-");
  }
  return out;
}

// The figures of an analysis step in one line: its outcome in the journal.
std::string AllanOutcome(const RecordAnalysis& a) {
  return fmt::format("Allan, {}: noise density{}; bias instability{}", a.unit,
                     Figures(a, &AllanReadOffs::noise_density), Figures(a, &AllanReadOffs::bias_instability));
}

std::string NoiseOutcome(const analysis::NoiseReport& n) {
  std::string out = fmt::format("noise, {}: std", n.unit);
  const analysis::RecordNoise& r = n.records.front();
  for (size_t a = 0; a < 3; ++a) out += fmt::format(" {} {:.4g}", "xyz"[a], r.axes[a].std);
  out += "; density";
  for (size_t a = 0; a < 3; ++a) out += fmt::format(" {} {:.4g}", "xyz"[a], r.axes[a].density);
  return out;
}

}  // namespace

CalibrationRequest WizardCalibrationRequest(const Procedure& procedure, const GravitySpec& gravity,
                                            const std::vector<EquipmentItem>& equipment,
                                            const std::optional<NoiseFloor>& lowered,
                                            std::string source_name) {
  CalibrationRequest request;
  request.source_name = std::move(source_name);
  request.gravity = gravity;
  request.references = ToReferenceUncertainties(equipment, gravity.sigma_mps2);
  request.screening.adc_range = procedure.adc_range;
  if (lowered) {
    // The captures judged with the floor before it was lowered are judged again: the ones the
    // wizard left out (and captured again) are left out of the fit with the reason.
    OfflineStabilityOptions stability;
    stability.stability.std_multiplier = procedure.std_multiplier;
    stability.stability.trend_multiplier = procedure.trend_multiplier;
    stability.noise_floor_counts = lowered->std_counts;
    request.stability = stability;
  }
  return request;
}

CalibrationSteps::CalibrationSteps(const Procedure& procedure, SessionModel& model,
                                   GravitySpec gravity, std::string session_name,
                                   WizardOutputs* outputs)
    : procedure_(procedure), model_(model), gravity_(gravity),
      session_name_(std::move(session_name)), outputs_(outputs), equipment_(procedure.equipment) {}

void CalibrationSteps::set_equipment(std::vector<EquipmentItem> equipment) {
  outcome_.reset();
  equipment_ = std::move(equipment);
}

void CalibrationSteps::set_gravity(const GravitySpec& gravity) {
  if (gravity.gravity_mps2 != gravity_.gravity_mps2 || gravity.source != gravity_.source) outcome_.reset();
  gravity_ = gravity;
}

void CalibrationSteps::set_noise_floor(const std::optional<NoiseFloor>& lowered) {
  const bool changed = lowered.has_value() != lowered_floor_.has_value() ||
                       (lowered && lowered->std_counts != lowered_floor_->std_counts);
  if (changed) outcome_.reset();
  lowered_floor_ = lowered;
}

const CalibrationOutcome& CalibrationSteps::Run() {
  if (outcome_ && outcome_captures_ == model_.captures().size()) return *outcome_;
  CalibrationRequest request =
      WizardCalibrationRequest(procedure_, gravity_, equipment_, lowered_floor_, session_name_);
  // A capture taken again (redo) is superseded: out of the fit.
  for (const JournalCapture& c : model_.captures())
    if (!c.superseded()) request.captures.push_back(c.capture);
  outcome_ = CalibrateCaptures(std::move(request));
  outcome_captures_ = model_.captures().size();
  return *outcome_;
}

StepOutcome CalibrationSteps::Fit() {
  outcome_.reset();  // the fit step always fits what the session holds now
  const CalibrationOutcome& o = Run();
  StepOutcome out;
  const FitSummary& fit = o.diagnosis.base;
  if (!fit.IsUsable()) {
    out.problem = "the fit is not usable: " + fit.message;
    out.hint = "r runs the fit again; b goes back to a skipped step to capture it";
    return out;
  }
  // Plain words on the screen (fit_words.h); the statistics one key away.
  const Calibration cal = o.MakeCalibration(false);
  out.lines = WrapWords("Gravity: " + gravity_.Describe(), 78);
  out.details = out.lines;
  for (std::string& line : FitInPlainWords(cal)) out.lines.push_back(std::move(line));
  for (std::string& line : SplitLines(FormatFitReport(cal, fit))) out.details.push_back(std::move(line));
  return out;
}

StepOutcome CalibrationSteps::Diagnosis() {
  const CalibrationOutcome& o = Run();
  StepOutcome out;
  // Plain words on the screen (diagnosis_words.h); the statistics one key away.
  out.details = SplitLines(FormatDiagnosis(o.diagnosis));
  if (o.usable()) out.lines = DiagnosisInPlainWords(o.diagnosis, gravity_.gravity_mps2).lines;
  if (const std::string note = GravityAmbiguityNote(gravity_, o.diagnosis.adopted_names()); !note.empty()) {
    out.lines.push_back("");
    for (const std::string& line : WrapWords("Gravity: " + WithPlainEffectNames(note, o.diagnosis.adopted_names()), 78))
      out.lines.push_back(line);
    out.details.push_back("");
    for (const std::string& line : WrapWords("Gravity: " + note, 78)) out.details.push_back(line);
  }
  if (!o.usable()) {
    out.problem = "the fit is not usable: " + o.diagnosis.base.message;
    out.hint = "s skips the diagnosis (the report needs a usable fit)";
  }
  return out;
}

SessionGaps CalibrationSteps::GapsOf(const CalibrationOutcome& o, const Calibration& cal,
                                     const SessionGaps& session_gaps) {
  SessionGaps gaps = session_gaps;
  left_out_by_fit_.clear();
  const std::vector<std::string> left_out = AddLeftOutByTheFit(procedure_, model_, cal, &gaps);
  for (const ProcedureStep& s : procedure_.steps)
    if (s.required && std::find(left_out.begin(), left_out.end(), s.id) != left_out.end())
      left_out_by_fit_.push_back(s.id);
  gaps.gravity_ambiguity = GravityAmbiguityNote(gravity_, o.diagnosis.adopted_names());
  return gaps;
}

ReportInputs CalibrationSteps::Inputs(const Calibration& cal, const ReportMeta& meta,
                                      const SessionGaps& gaps) const {
  ReportInputs in;
  in.calibration = cal;
  in.meta = meta;
  FillMetaFromInputs(model_.inputs(), &in.meta);  // what was typed wins over the defaults
  in.bench_time = BenchTimeFromInputs(model_.inputs());
  for (const JournalCapture& c : model_.captures())  // their statistics: no copy of the samples
    if (!c.superseded()) in.captures.push_back(ReportStatsOf(c.capture));
  in.limits = procedure_.limits;
  in.equipment = equipment_;
  in.nominal_bias_counts = procedure_.nominal.bias_counts;
  in.nominal_scale_counts_per_mps2 = procedure_.nominal.scale_counts_per_mps2;
  in.gaps = gaps;
  return in;
}

StepOutcome CalibrationSteps::Report(bool adopt_effects, const ReportMeta& meta,
                                     const SessionGaps& session_gaps) {
  const CalibrationOutcome& o = Run();
  StepOutcome out;
  const bool adopt = adopt_effects && !o.diagnosis.adopted.empty();
  const FitSummary& summary = o.Fit(adopt);
  if (!summary.IsUsable()) {
    out.problem = "no calibration: the fit is not usable: " + summary.message;
    out.hint = "q leaves; the captures are kept in the session";
    return out;
  }
  const Calibration cal = o.MakeCalibration(adopt);
  const SessionGaps gaps = GapsOf(o, cal, session_gaps);
  model_.RecordResult(SessionResultJsonText(cal, gaps));
  const ReportInputs in = Inputs(cal, meta, gaps);
  const ReportModel verdict = BuildReportModel(in);
  const std::vector<std::string> next = NextSteps(in, verdict, session_name_, left_out_by_fit_);
  // The verdict first, on the step's first screen: what failed, what is missing, what to do,
  // where the report is; then the fit behind it.
  const auto add = [&](const std::string& text, size_t indent) {
    for (std::string& line : WrapWords(std::string(indent, ' ') + text, 78)) out.lines.push_back(std::move(line));
  };
  out.lines.push_back(fmt::format("Verdict: {}", VerdictToString(verdict.verdict)));
  for (const LimitCheck& c : verdict.checks)
    if (!c.pass) add("not met: " + (c.why.empty() ? c.what : c.why), 2);
  for (const SessionGaps::Step& s : gaps.steps)
    add(fmt::format("missing: {} ({}{}): {}", s.title, s.id, s.required ? ", required" : "", s.why), 2);
  for (const std::string& why : verdict.incomplete) add("INCOMPLETE: " + why, 2);
  if (!next.empty()) out.lines.push_back("Next:");
  for (const std::string& step : next) add("- " + step, 2);
  std::vector<std::string> paths;
  if (outputs_ != nullptr) {
    try {
      paths = outputs_->WriteReports(in);
      for (const std::string& path : paths) out.lines.push_back("Report written to " + path);
    } catch (const Error& e) {
      out.lines.push_back(std::string("The report was not written: ") + e.what());
    }
  }
  out.lines.push_back("");
  add("Gravity: " + gravity_.Describe(), 0);
  for (std::string& line : FitInPlainWords(cal)) out.lines.push_back(std::move(line));
  out.lines.push_back(adopt ? fmt::format("Effects adopted: {}", fmt::join(o.diagnosis.adopted_names(), ", "))
                            : "Model: the nine-parameter base model");
  final_summary_ = BuildFinalSummary(verdict, paths, next);
  out.details = final_summary_->details;
  for (std::string& line : SplitLines(FormatFitReport(cal, summary))) out.details.push_back(std::move(line));
  return out;
}

void CalibrationSteps::Recap(bool adopt_effects, const ReportMeta& meta, const SessionGaps& session_gaps) {
  const CalibrationOutcome& o = Run();
  const bool adopt = adopt_effects && !o.diagnosis.adopted.empty();
  if (!o.Fit(adopt).IsUsable()) return;  // the report step said so; nothing to recap
  const Calibration cal = o.MakeCalibration(adopt);
  const ReportInputs in = Inputs(cal, meta, GapsOf(o, cal, session_gaps));
  const ReportModel verdict = BuildReportModel(in);
  final_summary_ = BuildFinalSummary(verdict, outputs_ != nullptr ? outputs_->ReportPaths() : std::vector<std::string>{},
                                     NextSteps(in, verdict, session_name_, left_out_by_fit_));
}

// The analysis of a record step: read back from the journal one chunk at a time (a 12-hour
// record does not fit the view), analysed, and shown.
StepOutcome CalibrationSteps::Analysis(const ProcedureStep& step, std::string* outcome) {
  StepOutcome out;
  if (model_.RecordSummaryOf(step.record_step).num_samples == 0) {
    out.problem = fmt::format("nothing to analyse: the record step '{}' holds no samples (skipped?)",
                              step.record_step);
    out.hint = "s skips the analysis; b goes back to the record";
    return out;
  }
  try {
    if (step.method == "allan") {
      const RecordAnalysisOptions options;
      const RecordAnalysis a = AnalyzeJournalRecord(model_, step.record_step, options);
      const std::string source = session_name_ + ":" + step.record_step;
      out.lines = SplitLines(FormatAllanText(a, source));
      *outcome = AllanOutcome(a);
      if (outputs_ != nullptr) {
        const std::string path = outputs_->WriteAllan(a, source, options.drift.window_s);
        out.lines.push_back(fmt::format("Allan analysis written to {} (accelcal report --allan, "
                                        "accelcal export-cal --to kalibr --allan).", path));
      }
    } else {
      // Read back chunk by chunk at each of the analysis's passes: bounded memory at any rate.
      const analysis::NoiseReport n = analysis::AnalyzeNoiseSources(
          {analysis::JournalNoiseRecord(model_, step.record_step, step.record_step, "")});
      out.lines = SplitLines(FormatNoiseText(n));
      out.lines.push_back("The day-to-day repeatability of the bias takes three such records on "
                          "different days: accelcal noise DEVICE.");
      *outcome = NoiseOutcome(n);
    }
  } catch (const Error& e) {
    out.problem = std::string("the analysis failed: ") + e.what();
    out.hint = "s skips the analysis; the record is kept in the session";
  }
  return out;
}

}  // namespace accelcal
