// The wizard engine on the virtual bench at speed 0 with a memory journal, for the tests of the
// checks that guard a calibration (wizard_checks_test.cpp).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/acquire/sim/scenario.h"
#include "accelcal/acquire/source/sim_source.h"
#include "accelcal/app/wizard/virtual_lab.h"
#include "accelcal/app/wizard/wizard_engine.h"
#include "accelcal/io/procedure_file.h"
#include "accelcal/session/procedure.h"
#include "accelcal/session/session_journal.h"

namespace accelcal::testing {

inline Procedure FullProcedure() {
  return LoadProcedure(std::string(ACCELCAL_SOURCE_DIR) + "/procedures/full_calibration.toml");
}

// The shipped procedure with 3 s captures (the checks are the same; the test time is not). Its
// [target] is taken out: with one the capture plan sizes every capture (15 s and more on the
// virtual lab's equipment) and the steps' 3 s would not be what runs; the plan's own tests use
// FullProcedure().
inline Procedure ShortFullProcedure() {
  Procedure p = FullProcedure();
  p.target = ProcedureTarget{};
  for (ProcedureStep& s : p.steps)
    if (KeepsCapture(s.kind)) s.duration_s = 3.0;  // the poses (the repeat too) and the runs
  return p;
}

inline SimOptions FastSim() {
  SimOptions o;
  o.speed = 0.0;
  o.bump_probability = 0.0;
  return o;
}

// The seed procedure's steps of the kinds given (and none other), in order.
inline Procedure StepsOf(Procedure p, const std::function<bool(const ProcedureStep&)>& keep) {
  std::vector<ProcedureStep> steps;
  for (const ProcedureStep& s : p.steps)
    if (keep(s)) steps.push_back(s);
  p.steps = steps;
  return p;
}

// `options` as `accelcal wizard --source sim` makes them: the scenario's lab offered at the
// welcome (virtual_lab.h), its gravity unless the options give one other than the standard.
inline WizardOptions OnVirtualBench(const sim::Scenario& scenario, WizardOptions options) {
  OfferVirtualLab(scenario, !options.gravity.is_standard(), &options);
  return options;
}

// A sim, a journal and an engine over them (declared in that order: the engine borrows both).
// The welcome offers the scenario's lab, as the command line does on the virtual bench.
struct WizardRig {
  WizardRig(Procedure procedure, const sim::Scenario& scenario, std::shared_ptr<SessionJournal> shared = nullptr,
            WizardOptions options = WizardOptions{"test", "op", "SN1", {}, 2.0, {}})
      : sim(scenario, FastSim()),
        journal(shared ? std::move(shared) : std::shared_ptr<SessionJournal>(MakeMemoryJournal())),
        engine(std::move(procedure), sim, *journal, OnVirtualBench(scenario, std::move(options))) {}
  SimSource sim;
  std::shared_ptr<SessionJournal> journal;
  WizardEngine engine;
};

inline bool Busy(const WizardView& v) {
  return (v.screen == WizardScreen::kCapturing || v.screen == WizardScreen::kRecording) && !v.input;
}

// Polls while the engine is busy; returns the problems seen on the way.
inline std::vector<std::string> PollUntilQuestion(WizardEngine& e, int max_polls = 5000) {
  std::vector<std::string> problems;
  for (int i = 0; i < max_polls && Busy(e.View()); ++i) {
    e.Poll(0.0);
    const std::string p = e.View().problem;
    if (!p.empty() && (problems.empty() || problems.back() != p)) problems.push_back(p);
  }
  return problems;
}

// Accepts every question until `stop` says so or the wizard finishes; returns every problem
// shown on the way (each once in a row).
inline std::vector<std::string> AcceptUntil(WizardEngine& e, const std::function<bool(const WizardView&)>& stop,
                                            int max_steps = 2000) {
  std::vector<std::string> problems;
  for (int i = 0; i < max_steps; ++i) {
    for (const std::string& p : PollUntilQuestion(e)) problems.push_back(p);
    const WizardView v = e.View();
    if (!v.problem.empty() && (problems.empty() || problems.back() != v.problem)) problems.push_back(v.problem);
    if (v.finished || stop(v)) return problems;
    e.Handle({IntentKind::kAccept, ""});
  }
  ADD_FAILURE() << "the wizard did not get there";
  return problems;
}

inline bool Never(const WizardView&) { return false; }

inline bool AnyContains(const std::vector<std::string>& texts, const std::string& part) {
  for (const std::string& t : texts)
    if (t.find(part) != std::string::npos) return true;
  return false;
}

}  // namespace accelcal::testing
