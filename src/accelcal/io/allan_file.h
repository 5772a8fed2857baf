// The Allan analysis file (`accelcal allan ... -o allan.json`): the record analysis of
// analysis/record_analysis.h as JSON, for reports, Kalibr's imu.yaml and other tools.
//
//   {
//     "format": "accelcal-allan", "version": 1,
//     "source": "rec.txt",                      // what was analysed
//     "unit": "counts" | "m/s^2",               // of every figure below
//     "rate_hz": 100.0, "rate_estimated": true,
//     "samples": 4320000, "missing_samples": 0, "duration_s": 43200.0,
//     "gaps": [{"t_before_s": .., "t_after_s": .., "missing_samples": ..}],
//     "temperature_c": {"min": .., "max": ..} | null,
//     "conventions": {...},                     // the definitions below, in words
//     "axes": {
//       "x": {
//         "noise_density": ..,          // unit/sqrt(Hz): slope -1/2 line at tau = 1 s
//         "bias_instability": ..,       // unit: curve minimum / 0.664
//         "bias_instability_tau_s": ..,
//         "random_walk": ..,            // unit/sqrt(s): slope +1/2 line at tau = 3 s
//         "white_noise_observed": true, "random_walk_observed": false,
//         "max_drift": ..,              // unit: peak to peak of 1-minute means
//         "drift_window_s": 60,
//         "temperature_correlation": .. | null, "temperature_slope_per_c": .. | null,
//         "notes": ["..."],
//         "tau_s": [..], "adev": [..], "adev_lo": [..], "adev_hi": [..],
//         "edf": [..], "num_terms": [..], "alpha": [..]
//       }, "y": {..}, "z": {..}
//     }
//   }
// A figure that cannot be given (too short a record) is null, never a made-up number. The
// report reads such a file (and the shape of docs/certificate.md, "Reports") as an AllanSection.
#pragma once

#include <string>

#include "accelcal/analysis/record_analysis.h"
#include "accelcal/report/report_model.h"

namespace accelcal {

// The file's text (2-space indent, a final newline).
std::string AllanFileText(const RecordAnalysis& analysis, const std::string& source,
                          double drift_window_s);
// Writes `text` to `path` atomically. Throws accelcal::Error when it cannot.
void WriteAllanFile(const std::string& path, const std::string& text);
// An Allan file (or docs/certificate.md's report shape) read strictly as the report's section; InputError
// naming the file and field otherwise. ReadAllanFile reads `path` once (a pipe works).
AllanSection ParseAllanText(const std::string& text, const std::string& source);
AllanSection ReadAllanFile(const std::string& path);

}  // namespace accelcal
