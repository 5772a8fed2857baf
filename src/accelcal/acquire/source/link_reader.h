// Reading a ByteLink for a line source (StreamSource: one sensor; ColumnsSensorSet: several on
// one line): open it when its back-off says so, wait for bytes within the caller's deadline with
// poll(), take what is there without waiting (at most 1 MiB per call, so that a fire-hose cannot
// starve the caller), and close it at its end: a link that reopens (serial, TCP) is retried with
// back-off, one that does not (a file, standard input) is finished. What happens is told to the
// source's LinkEvents, which parse the bytes and keep the status.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "accelcal/acquire/source/byte_link.h"
#include "accelcal/acquire/source/reconnect_backoff.h"
#include "accelcal/acquire/source/source_options.h"

namespace accelcal {

class LinkEvents {
 public:
  virtual ~LinkEvents() = default;
  virtual void OnLinkOpen() = 0;
  virtual void OnLinkOpenFailed(const std::string& error) = 0;
  virtual void OnBytes(std::string_view bytes) = 0;
  // The link's last byte came ("LINK: why"); `reopens`: it is retried (drop the partial line),
  // else the input is done (finish it); `failed`: with an error.
  virtual void OnLinkEnd(const std::string& described, bool failed, bool reopens) = 0;
};

class LinkReader {
 public:
  // Reads options' reconnect_initial_s and reconnect_max_s.
  LinkReader(std::unique_ptr<ByteLink> link, const SourceOptions& options);
  ~LinkReader();
  LinkReader(const LinkReader&) = delete;
  LinkReader& operator=(const LinkReader&) = delete;

  // Opens the link when due, then waits until deadline_s (wall clock) for bytes and hands them
  // over. Returns false when the link is not open (not yet due, pending, failed, done).
  bool Fill(double deadline_s, LinkEvents& events);
  bool input_done() const { return input_done_; }
  std::string Describe() const { return link_->Describe(); }

 private:
  bool TryOpen(double deadline_s, LinkEvents& events);
  void ReadAvailable(LinkEvents& events);
  void EndOfData(const std::string& why, bool failed, LinkEvents& events);

  std::unique_ptr<ByteLink> link_;
  ReconnectBackoff backoff_;
  bool open_ = false;
  bool input_done_ = false;  // no more bytes will come (end of file or stdin)
  std::vector<char> buffer_;
};

}  // namespace accelcal
