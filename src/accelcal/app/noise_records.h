// Where the noise analysis's records come from: the sessions of a device in the session store
// whose procedure is the noise procedure (procedures/noise.toml), one record per session (the
// accepted capture of the procedure's `record` step, raw samples), dated by the session's
// creation day (UTC); or recording files (io/recording_reader.h), undated.
#pragma once

#include <string>
#include <vector>

#include "accelcal/analysis/noise_analysis.h"
#include "accelcal/base/sample_format.h"
#include "accelcal/base/sample_reader.h"
#include "accelcal/session/procedure.h"

namespace accelcal::analysis {

struct NoiseRecordSet {
  std::vector<NoiseRecord> records;  // by session creation time
  std::vector<std::string> notes;    // sessions passed over, and why
};

// The noise records of `device` among the sessions of `sessions_dir` whose procedure title is
// `noise_procedure.title`; a session without an accepted capture of one of the procedure's
// `record` steps is passed over with a note. Throws accelcal::Error when the procedure has no
// `record` step, the directory cannot be listed, or no record of the device is found: the
// message lists the devices that do have noise sessions there (or says there are none).
NoiseRecordSet NoiseRecordsOfDevice(const std::string& sessions_dir, const std::string& device,
                                    const Procedure& noise_procedure);

// A recording file as an undated record labelled by its path, read as `format` says; *summary
// (when not null) gets what the reading understood. Throws as ReadRecording.
NoiseRecord NoiseRecordFromFile(const std::string& path, const SampleFormat& format = {},
                                ReadingSummary* summary = nullptr);

}  // namespace accelcal::analysis
