// The noise analysis (analysis/noise_analysis.h) as text (a per-axis table per record and the
// day-to-day table; lines fit 80 columns; the spectra are left to the JSON) and as JSON:
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
// Numbers are written at full precision; a value that does not exist (NaN) is null.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "accelcal/analysis/noise_analysis.h"

namespace accelcal {

std::string FormatNoiseText(const analysis::NoiseReport& report);
nlohmann::json NoiseReportToJson(const analysis::NoiseReport& report);

}  // namespace accelcal
