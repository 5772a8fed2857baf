// The diagnosis in plain words (issue 15): each effect of the library in one sentence with its
// size in bench units, the recommended choice named, no statistics or jargon. The expected
// sizes are worked out by hand from the parameters (not by the code under test).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/app/wizard/diagnosis_words.h"
#include "accelcal/calibration/diagnosis/effect.h"

namespace accelcal {
namespace {

constexpr double kG = 9.80665;

AdoptedEffect Effect1(const std::string& name, std::vector<double> p, std::vector<double> sigma = {}) {
  AdoptedEffect e;
  e.name = name;
  e.parameters = std::move(p);
  e.uncertainty = sigma.empty() ? std::vector<double>(e.parameters.size(), 0.0) : std::move(sigma);
  return e;
}

TEST(DiagnosisWordsTest, EachEffectOfTheLibraryHasAPlainSentenceInBenchUnits) {
  EXPECT_EQ(EffectInPlainWords(Effect1("radius_offset", {0.003}, {0.0002}), kG),
            "the turntable radius seems 3.0 mm longer than entered (+-0.2 mm)");
  EXPECT_EQ(EffectInPlainWords(Effect1("radius_offset", {-0.0014}, {0.000034}), kG),
            "the turntable radius seems 1.4 mm shorter than entered (+-0.034 mm)");
  EXPECT_EQ(EffectInPlainWords(Effect1("rpm_scale", {-0.0025}, {0.0001}), kG),
            "the turntable seems to turn 0.25 % slower than entered (+-0.01 %)");
  EXPECT_EQ(EffectInPlainWords(Effect1("size_effect", {0.004, -0.002, 0.0}), kG),
            "each axis senses at a point off the one the radius was measured to: x +4.0, y -2.0, z +0.0 mm");
  AdoptedEffect tilt = Effect1("turntable_tilt", {0.0006});
  tilt.interpretation = "a spin axis tilted 1.98 deg from the vertical";
  EXPECT_EQ(EffectInPlainWords(tilt, kG),
            "the turntable's spin axis is not vertical: a spin axis tilted 1.98 deg from the vertical; "
            "level the turntable");
  // q g^2: 0.02 * 96.17 = 1.92 counts at 1 g.
  EXPECT_EQ(EffectInPlainWords(Effect1("quadratic_nonlinearity", {0.02, -0.015, 0.01}), kG),
            "the sensor's output is not quite a straight line: at 1 g it bends by x +1.9, y -1.4, z +1.0 counts");
  // c3 g^3: 0.001 * 943.1 = 0.94 counts.
  EXPECT_EQ(EffectInPlainWords(Effect1("cubic_nonlinearity", {0.001, 0.0, -0.002}), kG),
            "the sensor's output is not quite a straight line (an S-bend): at 1 g by x +0.9, y +0.0, z -1.9 counts");
  // kappa g^2 / (3 sqrt 3): 1e-4 * 96.17 / 5.196 = 1.85 mm/s^2.
  EXPECT_EQ(EffectInPlainWords(Effect1("cross_axis_coupling", {1e-4}), kG),
            "each axis also responds to the other two together: 1.9 mm/s^2 on a corner pose");
  EXPECT_EQ(EffectInPlainWords(Effect1("temperature_bias", {0.5, -0.25, 0.0}), kG),
            "the zero-g level moves with temperature: x +0.50, y -0.25, z +0.00 counts per degC");
  EXPECT_EQ(EffectInPlainWords(Effect1("temperature_scale", {2e-4, 0.0, -1e-4}), kG),
            "the sensitivity changes with temperature: x +0.020, y +0.000, z -0.010 % per degC");
  // 0.01 counts/s = 0.60 counts per minute.
  EXPECT_EQ(EffectInPlainWords(Effect1("bias_drift", {0.01, 0.0, -0.005}), kG),
            "the zero-g level drifts during the session: x +0.60, y +0.00, z -0.30 counts per minute");
  // Every effect of the library is covered (none falls to the generic wording).
  for (const Effect* e : AllEffects()) {
    AdoptedEffect a = Effect1(std::string(e->Name()), std::vector<double>(static_cast<size_t>(e->NumParameters()), 0.001));
    EXPECT_EQ(EffectInPlainWords(a, kG).find("an effect the basic model lacks"), std::string::npos) << e->Name();
  }
  EXPECT_EQ(EffectInPlainWords(Effect1("new_effect", {1.5}), kG).rfind("an effect the basic model lacks (new_effect)", 0), 0u);
}

DiagnosisReport Found(std::vector<AdoptedEffect> effects) {
  DiagnosisReport r;
  r.adopted = std::move(effects);
  FitSummary base, final_fit;
  base.residual_rms_mps2 = 0.0213;
  final_fit.residual_rms_mps2 = 0.0031;
  r.stages = {base, final_fit};
  r.final_fit = final_fit;
  r.noise_rms_mps2 = 0.0029;
  return r;
}

TEST(DiagnosisWordsTest, ABenchErrorIsToBeCorrectedAndRefitRecommended) {
  const DiagnosisWords w = DiagnosisInPlainWords(Found({Effect1("radius_offset", {0.003}, {0.0002})}), kG);
  ASSERT_TRUE(w.asks);
  EXPECT_EQ(w.prompt, "The turntable radius seems 3.0 mm longer than entered (+-0.2 mm): correct it and refit "
                      "(recommended), or keep the basic model?");
  EXPECT_EQ(w.lines[1].find("radius_offset"), std::string::npos);
  EXPECT_EQ(w.recommended_action, "refit (recommended)");
  ASSERT_EQ(w.lines.size(), 3u);
  EXPECT_EQ(w.lines[0], "The diagnosis found one thing the basic model lacks:");
  EXPECT_EQ(w.lines[1], "- the turntable radius seems 3.0 mm longer than entered (+-0.2 mm).");
  EXPECT_EQ(w.lines[2], "With it the fit's error drops from 21.3 to 3.1 mm/s^2 (the noise explains 2.9).");
}

TEST(DiagnosisWordsTest, ABenchErrorAndASensorEffectTogether) {
  const DiagnosisWords w = DiagnosisInPlainWords(
      Found({Effect1("radius_offset", {0.003}), Effect1("quadratic_nonlinearity", {0.02, -0.015, 0.01})}), kG);
  EXPECT_EQ(w.prompt, "A wrong turntable radius and a bent response: correct the bench and the sensor's model "
                      "and refit (recommended), or keep the basic model?");
  EXPECT_EQ(WithPlainEffectNames("radius_offset found while gravity", {"radius_offset", "rpm_scale"}),
            "a wrong turntable radius found while gravity");
  EXPECT_EQ(w.recommended_action, "refit (recommended)");
  EXPECT_EQ(w.lines[0], "The diagnosis found 2 things the basic model lacks:");
  const DiagnosisWords sensor = DiagnosisInPlainWords(Found({Effect1("bias_drift", {0.01, 0.0, 0.0})}), kG);
  EXPECT_EQ(sensor.recommended_action, "add it (recommended)");
  EXPECT_NE(sensor.prompt.find(": add it to the calibration (recommended), or keep the basic model?"),
            std::string::npos) << sensor.prompt;
}

// A rival outside the library (rival_explanations.h) is said in bench words, never by its name.
TEST(DiagnosisWordsTest, ARivalExplanationIsSaidInBenchWords) {
  DiagnosisReport r;
  r.unexplained = true;
  r.ambiguous = {"temperature_bias", "turntable_bias_shift"};
  r.next_captures = "to tell turntable_bias_shift apart: take a static pose again between the turntable runs";
  const DiagnosisWords w = DiagnosisInPlainWords(r, 9.80665);
  std::string all;
  for (const std::string& line : w.lines) all += line + "\n";
  EXPECT_NE(all.find("a zero-g level that shifts while the table turns"), std::string::npos) << all;
  EXPECT_NE(all.find("take a static pose again between the turntable runs"), std::string::npos) << all;
  EXPECT_EQ(all.find("turntable_bias_shift"), std::string::npos) << all;
  EXPECT_EQ(all.find("temperature_bias"), std::string::npos) << all;
}

TEST(DiagnosisWordsTest, NothingFoundSaysSoWithoutJargon) {
  DiagnosisReport r;
  r.consistent = true;
  r.conclusion = "the nine-parameter model explains the captures: no effect added";
  DiagnosisWords w = DiagnosisInPlainWords(r, kG);
  EXPECT_FALSE(w.asks);
  ASSERT_EQ(w.lines.size(), 1u);
  EXPECT_EQ(w.lines[0], "The basic model explains every capture within the sensor's noise: nothing to correct.");
  r.consistent = false;
  r.unexplained = true;
  r.ambiguous = {"bias_drift", "temperature_bias"};
  r.next_captures = "a pose at the start and the end of the session";
  w = DiagnosisInPlainWords(r, kG);
  ASSERT_EQ(w.lines.size(), 3u);
  EXPECT_EQ(w.lines[1], "Two explanations fit alike and these captures cannot tell them apart: a drifting "
                       "zero-g level or a zero-g level moving with temperature.");
  EXPECT_EQ(w.lines[2], "To find out, capture a pose at the start and the end of the session");
  for (const std::string& line : w.lines) {
    EXPECT_EQ(line.find("seed"), std::string::npos) << line;
    EXPECT_EQ(line.find('_'), std::string::npos) << line;  // no internal names
  }
}

}  // namespace
}  // namespace accelcal
