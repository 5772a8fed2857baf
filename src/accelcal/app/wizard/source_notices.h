// What the live source noticed, on the wizard's screen in the bench's words (a device that
// restarted, a link lost and back, samples lost on the way), with the figures behind it (the
// source's own sentence and its counts) one key away. The engine updates it after every read
// of the source; a key acknowledges what is said (it stays until then, so a notice during a
// capture is still there when the technician looks).
//
// Lost samples are said when they begin and again each time their count passes a power of ten
// (1, 10, 100, ...), not at every frame: a link that drops 5 % of its frames is a fact to know,
// not a stream of alarms.
#pragma once

#include <string>

#include "accelcal/acquire/source/source_status.h"

namespace accelcal {

class SourceNotices {
 public:
  // After a read of the source: `result` what happened in it, `status` the source's status.
  void Update(const ReadResult& result, const SourceStatus& status);
  // A key was pressed: what was said has been seen.
  void Acknowledge();

  // In the bench's words; empty when there is nothing to say.
  const std::string& text() const { return text_; }
  // The figures: the source's own words and its counts; empty with text().
  const std::string& detail() const { return detail_; }

 private:
  void Say(std::string text, const SourceStatus& status, const std::string& figures);

  std::string text_;
  std::string detail_;
  long lost_said_ = 0;       // the count of lost samples last said
  std::string seen_notice_;  // the source's latest notice as last seen
};

// The bench's words for what a notice of `kind` tells.
std::string SourceNoticeWords(SourceNoticeKind kind);

}  // namespace accelcal
