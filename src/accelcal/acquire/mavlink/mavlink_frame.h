// MAVLink framing, both versions (the MAVLink serialization documentation, "Packet Format"):
//
//   v1: 0xFE len seq sys comp msgid                 payload[len] crc_lo crc_hi
//   v2: 0xFD len incompat compat seq sys comp msgid[3] payload[len] crc_lo crc_hi [signature 13]
//
// The CRC (x25_crc.h) covers every byte after the start marker up to the payload's end, then
// the message's CRC_EXTRA (mavlink_messages.h). A v2 sender drops the payload's trailing zero
// bytes; the reader zero-fills it to the message's length. A signed v2 frame (incompat flag 1)
// carries 13 bytes of signature after the CRC: accepted, the signature skipped (accelcal has no
// key to check it with). A frame with any other incompatibility flag must be dropped (the
// specification's rule for flags a reader does not understand).
//
// The parser takes bytes as they come, in reads of any size, and never stops for bad input: a
// bad CRC drops the start byte and looks for the next frame (a corrupt length must not swallow
// good frames after it), bytes before a start marker are garbage, a message outside our table is
// skipped by its length (its CRC cannot be checked without its CRC_EXTRA), a payload longer
// than its message allows (or a v1 one shorter) is a wrong length. Each is counted and the
// latest said in words.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "accelcal/acquire/mavlink/mavlink_messages.h"

namespace accelcal::mavlink {

struct Frame {
  int version = 2;
  std::uint8_t seq = 0, system = 0, component = 0;
  std::uint32_t message = 0;
  Payload payload;         // zero-filled to the message's full length
  int sent_length = 0;     // payload bytes as sent
  bool signed_frame = false;
};

struct FrameCounters {
  long frames = 0;          // good frames of messages in our table
  long other_messages = 0;  // frames of messages accelcal does not read, skipped unchecked
  long bad_crc = 0;
  long wrong_length = 0;
  long bad_flags = 0;       // v2 incompatibility flags other than signing
  long garbage_bytes = 0;   // bytes outside any frame
  long signed_frames = 0;
  long v1_frames = 0;
  std::uint32_t last_other_message = 0;
};

class FrameParser {
 public:
  // Appends every frame completed by `bytes`; `bad` counts the bad frames and garbage runs found
  // (last_complaint() has the latest in words).
  void Feed(const std::uint8_t* bytes, size_t count, std::vector<Frame>* out, long* bad);
  // The link dropped: a frame cut short is not data.
  void Reset();

  const FrameCounters& counters() const { return counters_; }
  // "bad CRC on a HIGHRES_IMU frame from system 1 component 1 (seq 17)", "37 bytes that are not
  // MAVLink frames skipped", ...
  const std::string& last_complaint() const { return last_complaint_; }

 private:
  enum class Step { kFrame, kNeedMore, kBad, kSkipByte };
  Step TryFrame(std::vector<Frame>* out, size_t* used);
  void Complain(std::string text, long* bad);
  void EndGarbage(long* bad);

  std::vector<std::uint8_t> buffer_;
  size_t start_ = 0;  // first unread byte of buffer_
  long garbage_run_ = 0;
  bool after_bad_crc_ = false;  // the garbage that follows is the rest of that frame
  FrameCounters counters_;
  std::string last_complaint_;
};

// Encodes our frames: v2 (v1 when asked), system and component as a ground station, the
// sequence counting up.
class FrameWriter {
 public:
  FrameWriter(std::uint8_t system = 255, std::uint8_t component = 190)
      : system_(system), component_(component) {}
  // Throws accelcal::Error for a message outside the table.
  std::vector<std::uint8_t> Encode(std::uint32_t message, const Payload& payload, int version = 2);

 private:
  std::uint8_t system_, component_;
  std::uint8_t seq_ = 0;
};

}  // namespace accelcal::mavlink
