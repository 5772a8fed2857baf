#include "accelcal/app/wizard/source_notices.h"

#include <fmt/format.h>

namespace accelcal {
namespace {

// True once `count` reaches the next power of ten above `said` (1, 10, 100, ...).
bool PassedPowerOfTen(long count, long said) {
  long next = 1;
  while (next <= said) next *= 10;
  return count >= next;
}

}  // namespace

std::string SourceNoticeWords(SourceNoticeKind kind) {
  switch (kind) {
    case SourceNoticeKind::kRestarted:
      return "The device restarted (a reboot or a dip in its power); its samples go on. A capture "
             "running then is judged as usual; if the device was moved or touched, take it again.";
    case SourceNoticeKind::kRateRequest:
      return "The device did not take the sample rate asked for; it was asked the older way. The "
             "rate it really sends is in the status line.";
    case SourceNoticeKind::kCoarserReadings:
      return "The device does not send its finest readings; the wizard reads a coarser stream "
             "instead (its step is said at the noise floor).";
    case SourceNoticeKind::kDeviceSilent:
      return "The device has stopped answering: it is off, restarting, or its cable is out. Check "
             "it; the wizard goes on when its samples return.";
    case SourceNoticeKind::kSamplesLost:
      return "Samples were lost between the device and this computer; the captures go on with "
             "what arrives.";
    case SourceNoticeKind::kOther: break;
  }
  return "The device reports a change; the figures say what.";
}

void SourceNotices::Update(const ReadResult& result, const SourceStatus& status) {
  // A notice made between two reads (during a parameter exchange) marks no read's result: a
  // new sentence is a new notice too.
  const bool new_notice = result.notice || status.last_notice != seen_notice_;
  seen_notice_ = status.last_notice;
  // Lost samples are said by their count below (MAVLink's sequence gaps, IIO's overruns alike).
  if (new_notice && !status.last_notice.empty() && status.last_notice_kind != SourceNoticeKind::kSamplesLost)
    Say(SourceNoticeWords(status.last_notice_kind), status, status.last_notice);
  if (result.link_lost)
    Say("The link to the device was lost; the wizard is trying to reconnect.", status, status.link_error);
  if (result.reconnected) Say("The link to the device is back; samples arrive again.", status, "");
  if (status.lost_frames > lost_said_ && PassedPowerOfTen(status.lost_frames, lost_said_)) {
    lost_said_ = status.lost_frames;
    Say(fmt::format("Samples are being lost between the device and this computer ({} so far); the "
                    "captures go on with what arrives. Many lost samples mean a weak link or a busy "
                    "computer.",
                    status.lost_frames),
        status, status.last_notice_kind == SourceNoticeKind::kSamplesLost ? status.last_notice : "");
  }
}

void SourceNotices::Say(std::string text, const SourceStatus& status, const std::string& figures) {
  text_ = std::move(text);
  detail_ = figures.empty() ? status.BriefReport() : figures + "; " + status.BriefReport();
}

void SourceNotices::Acknowledge() {
  text_.clear();
  detail_.clear();
}

}  // namespace accelcal
