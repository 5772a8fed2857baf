// Where the noise analysis's records come from: the sessions of a device in the session store
// whose procedure is the noise procedure (procedures/noise.toml), one record per session (the
// accepted capture of the procedure's `record` step, raw samples), dated by the session's
// creation day (UTC); or recording files (io/recording_reader.h), undated. Each is a source the
// analysis reads in passes (noise_analysis.h), one chunk or block in memory at a time.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accelcal/analysis/noise_analysis.h"
#include "accelcal/base/sample_format.h"
#include "accelcal/base/sample_reader.h"
#include "accelcal/session/procedure.h"
#include "accelcal/session/session_journal.h"

namespace accelcal::analysis {

struct NoiseRecordSet {
  std::vector<NoiseRecordSource> records;  // by session creation time
  std::vector<std::string> notes;    // sessions passed over, and why
};

// The noise records of `device` among the sessions of `sessions_dir` whose procedure title is
// `noise_procedure.title`; a session without an accepted capture of one of the procedure's
// `record` steps is passed over with a note. Throws accelcal::Error when the procedure has no
// `record` step, the directory cannot be listed, or no record of the device is found: the
// message lists the devices that do have noise sessions there (or says there are none).
NoiseRecordSet NoiseRecordsOfDevice(const std::string& sessions_dir, const std::string& device,
                                    const Procedure& noise_procedure);

// A recording file as an undated record labelled by its path, read as `format` says, block by
// block at every pass; a pipe or FIFO, which cannot be read twice, is read once into memory.
// *summary (when not null, and alive until the analysis is done) gets what the reading
// understood, at the first pass. Replaying throws as ReadRecording.
NoiseRecordSource NoiseRecordFromFile(const std::string& path, const SampleFormat& format = {},
                                      ReadingSummary* summary = nullptr);

// The record of `step_id` in `journal` (which must outlive the source), chunk by chunk; a
// replay throws as ReadRecord when none of its chunks can be read.
NoiseRecordSource JournalNoiseRecord(const SessionJournal& journal, const std::string& step_id,
                                     const std::string& label, const std::string& date);

}  // namespace accelcal::analysis
