// The record analysis (record_analysis.h) of a recording file, streamed block by block
// (io/recording_stream.h): a 12-hour record at 1 kHz is analysed in bounded memory. With a
// calibration, each sample is corrected first (apply.h) and the figures are in m/s^2; without,
// in raw counts.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "accelcal/analysis/record_analysis.h"
#include "accelcal/base/sample_format.h"
#include "accelcal/base/sample_reader.h"
#include "accelcal/io/calibration_file.h"
#include "accelcal/session/session_journal.h"

namespace accelcal {

// `path` is a recording file ("-": standard input), read as `format` says (base/sample_reader.h);
// with a calibration its readings are in the calibration's unit (a different declared one is an
// error); without one, readings a logger converted (--unit m/s^2 or g) are analysed in m/s^2
// (g as 9.80665 m/s^2, the unit's definition). `progress`, when set, is called now and then
// with the samples read so far; *summary (when not null) gets what the reading understood.
// Throws accelcal::Error / InputError (FILE:LINE:COL) on a file that cannot be read or is
// malformed, and Error when the calibration needs a temperature the record lacks.
RecordAnalysis AnalyzeRecordingFile(const std::string& path, const RecordAnalysisOptions& options,
                                    const std::optional<Calibration>& calibration,
                                    const std::function<void(long samples)>& progress = {},
                                    const SampleFormat& format = {},
                                    ReadingSummary* summary = nullptr);

}  // namespace accelcal

namespace accelcal {

// The record analysis of the record step `step_id` of a session journal (the wizard streams
// records there in chunks: session_journal.h), read one chunk at a time; in counts, or in m/s^2
// with a calibration, as for a file. The gaps of a resumed record show as steps in its t and are
// handled as in a file, as are the holes of damaged chunks; damaged last chunks are a gap at the
// record's end (its readings missing). Throws accelcal::Error when the step has no record.
RecordAnalysis AnalyzeJournalRecord(const SessionJournal& journal, const std::string& step_id,
                                    const RecordAnalysisOptions& options,
                                    const std::optional<Calibration>& calibration = std::nullopt);

// A record named by the one who asks (`accelcal allan`), analysed whatever it is: a wizard
// session's record when `path` is a session file (app/calibration_input.h's test; its record
// step `step_id`, empty: the first), else a recording ("-": standard input; a ROS bag, though
// a .db3 is an SQLite file too) read as `format`.
// Throws as AnalyzeRecordingFile, and accelcal::Error naming the session when it holds no
// record, or none at `step_id` (the message lists its records).
struct RecordInputAnalysis {
  RecordAnalysis analysis;
  std::string source;                     // what was analysed: "PATH", or "PATH:STEP"
  std::optional<ReadingSummary> reading;  // a recording's: what the reading understood
};
RecordInputAnalysis AnalyzeRecordInput(const std::string& path, const std::string& step_id,
                                       const RecordAnalysisOptions& options,
                                       const std::optional<Calibration>& calibration,
                                       const SampleFormat& format);

}  // namespace accelcal
