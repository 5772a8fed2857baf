// The noise analysis file (`accelcal noise --format json`), format "accelcal-noise/1":
//
//   {"format": "accelcal-noise/1", "unit": "counts" | "m/s^2",
//    "density_unit": "<unit>/sqrt(Hz)", "psd_unit": "<unit>^2/Hz", "calibration": null | "...",
//    "records": [{"label", "date" (null when unknown), "n_samples", "rate_hz", "duration_s",
//                 "welch": {"segment_length", "segments", "resolution_hz"},
//                 "flat_band_hz": [low, high], "flat_band_bins",
//                 "axes": {"x": {"mean", "std", "std_counts", "density",
//                                "normality": {"test": "jarque-bera", "statistic", "p_value",
//                                              "skewness", "excess_kurtosis",
//                                              "verdict": "normal"|"not normal"|"quantized",
//                                              "note"}}, "y": ..., "z": ...},
//                 "spectrum": {"frequency_hz": [...], "x": [...], "y": [...], "z": [...]}}],
//    "repeatability": {"days", "records": [{"label", "date", "mean": [x, y, z]}],
//                      "std_of_means": [x, y, z] | null, "max_minus_min": [x, y, z] | null},
//    "warnings": ["..."]}
//
// Numbers are written at full precision; a value that does not exist (NaN) is null. The report
// reads such a file (or docs/certificate.md "Reports"' shorter shape) as a NoiseSection.
#pragma once

#include <string>

#include "accelcal/analysis/noise_analysis.h"
#include "accelcal/report/report_model.h"

namespace accelcal {

// The file's text (2-space indent, a final newline).
std::string NoiseFileText(const analysis::NoiseReport& report);
// A noise file read strictly as the report's section; InputError naming the file and field
// otherwise. ReadNoiseFile reads `path` once (a pipe works).
NoiseSection ParseNoiseText(const std::string& text, const std::string& source);
NoiseSection ReadNoiseFile(const std::string& path);

}  // namespace accelcal
