#include "accelcal/acquire/source/link_reader.h"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "accelcal/acquire/source/wall_clock.h"

namespace accelcal {
namespace {

using source_detail::WallNowS;

constexpr size_t kReadChunkBytes = 64 * 1024;
// Bytes taken from the link per Fill at most, so that a fire-hose cannot starve the caller.
constexpr size_t kMaxBytesPerCall = 1024 * 1024;

int PollTimeoutMs(double deadline_s) {
  const double left_s = deadline_s - WallNowS();
  if (left_s <= 0.0) return 0;
  return static_cast<int>(std::ceil(std::min(left_s, 3600.0) * 1000.0));
}

}  // namespace

LinkReader::LinkReader(std::unique_ptr<ByteLink> link, const SourceOptions& options)
    : link_(std::move(link)),
      backoff_(options.reconnect_initial_s, options.reconnect_max_s),
      buffer_(kReadChunkBytes) {}

LinkReader::~LinkReader() { link_->Close(); }

bool LinkReader::Fill(double deadline_s, LinkEvents& events) {
  if (!open_ && !TryOpen(deadline_s, events)) return false;
  pollfd p{link_->fd(), POLLIN, 0};
  const int rc = poll(&p, 1, PollTimeoutMs(deadline_s));
  if (rc < 0 && errno != EINTR) {
    EndOfData(std::string("poll: ") + std::strerror(errno), true, events);
  } else if (rc > 0) {
    ReadAvailable(events);
  }
  return true;
}

bool LinkReader::TryOpen(double deadline_s, LinkEvents& events) {
  const double now_s = WallNowS();
  if (!backoff_.Due(now_s, deadline_s)) return false;
  std::string error;
  switch (link_->Open(std::max(0.0, deadline_s - now_s), &error)) {
    case ByteLink::OpenStep::kOpen:
      open_ = true;
      backoff_.Succeeded();
      events.OnLinkOpen();
      return true;
    case ByteLink::OpenStep::kPending:
      return false;
    case ByteLink::OpenStep::kFailed:
      events.OnLinkOpenFailed(error);
      if (!link_->reopens()) input_done_ = true;
      backoff_.Failed(WallNowS());
      return false;
  }
  return false;
}

// Reads what is there (up to kMaxBytesPerCall) without waiting.
void LinkReader::ReadAvailable(LinkEvents& events) {
  size_t taken = 0;
  while (open_ && taken < kMaxBytesPerCall) {
    const ssize_t n = read(link_->fd(), buffer_.data(), buffer_.size());
    if (n > 0) {
      taken += static_cast<size_t>(n);
      events.OnBytes(std::string_view(buffer_.data(), static_cast<size_t>(n)));
      pollfd p{link_->fd(), POLLIN, 0};
      if (poll(&p, 1, 0) <= 0) return;
    } else if (n == 0) {
      EndOfData(link_->reopens() ? "the other end closed the link" : "end of data", false, events);
    } else if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) {
      return;
    } else {
      EndOfData(std::string("read: ") + std::strerror(errno), true, events);
    }
  }
}

// The link delivered its last byte (failed: with an error). A link that reopens is closed and
// retried; otherwise the input is done.
void LinkReader::EndOfData(const std::string& why, bool failed, LinkEvents& events) {
  link_->Close();
  open_ = false;
  const bool reopens = link_->reopens();
  if (reopens) backoff_.Failed(WallNowS());
  else input_done_ = true;
  events.OnLinkEnd(link_->Describe() + ": " + why, failed, reopens);
}

}  // namespace accelcal
