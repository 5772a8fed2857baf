// The noise analysis (analysis/noise_analysis.h) as text: a per-axis table per record and the
// day-to-day table; lines fit 80 columns; the spectra are left to the JSON (io/noise_file.h).
#pragma once

#include <string>

#include "accelcal/analysis/noise_analysis.h"

namespace accelcal {

std::string FormatNoiseText(const analysis::NoiseReport& report);

}  // namespace accelcal
