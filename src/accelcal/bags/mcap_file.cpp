#include "accelcal/bags/mcap_file.h"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "accelcal/bags/byte_reader.h"
#include "accelcal/bags/crc32.h"
#include "accelcal/base/error.h"
#include "accelcal/base/text_scan.h"

namespace accelcal::bags {
namespace {

constexpr uint8_t kMcapMagic[8] = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
constexpr size_t kRecordHead = 9;     // opcode and uint64 length
constexpr size_t kFooterBody = 20;    // summary_start, summary_offset_start, summary_crc

enum McapOp : uint8_t {
  kMcapHeader = 0x01,
  kMcapFooter = 0x02,
  kMcapSchema = 0x03,
  kMcapChannel = 0x04,
  kMcapMessage = 0x05,
  kMcapChunk = 0x06,
  kMcapChunkIndex = 0x08,
  kMcapStatistics = 0x0B,
  kMcapDataEnd = 0x0F,
};

constexpr size_t kMessageHead = 2 + 4 + 8 + 8;  // channel_id, sequence, log_time, publish_time
// Unchunked messages are handed over in batches of about this many bytes.
constexpr size_t kUnchunkedBatchBytes = size_t{1} << 20;
// A chunk that declares more than this uncompressed is taken for damage, not allocated.
constexpr uint64_t kMaxChunkBytes = uint64_t{1} << 32;

std::string_view McapRecordName(uint8_t op) {
  switch (op) {
    case kMcapHeader: return "Header";
    case kMcapSchema: return "Schema";
    case kMcapChannel: return "Channel";
    case kMcapMessage: return "Message";
    case kMcapChunk: return "Chunk";
    default: return "";
  }
}

}  // namespace

McapFile::McapFile(const std::string& path) : file_(path), channel_index_(65536, -1) {
  const uint8_t* d = file_.data();
  if (file_.size() < sizeof kMcapMagic || std::memcmp(d, kMcapMagic, sizeof kMcapMagic) != 0)
    throw Error(fmt::format("{}: not an MCAP file (it does not start with MCAP's magic bytes)",
                            file_.path()));
  pos_ = sizeof kMcapMagic;
  ReadSummary();
}

std::string McapFile::Description() const {
  std::string out = "MCAP file";
  std::string codecs;
  for (const std::string& c : compressions_) codecs += (codecs.empty() ? "" : " and ") + c;
  if (!codecs.empty()) out += ", " + codecs + " chunks";
  return out;
}

// The summary section, found through the footer at the file's end. A file without the trailing
// magic (cut, or not closed) has none; a summary whose CRC does not match is not trusted.
void McapFile::ReadSummary() {
  const size_t size = file_.size();
  const uint8_t* d = file_.data();
  const size_t tail = kRecordHead + kFooterBody + sizeof kMcapMagic;
  if (size < sizeof kMcapMagic + tail) return;
  if (std::memcmp(d + size - sizeof kMcapMagic, kMcapMagic, sizeof kMcapMagic) != 0) return;
  const size_t footer_at = size - tail;
  if (d[footer_at] != kMcapFooter || LoadLittle<uint64_t>(d + footer_at + 1) != kFooterBody) return;
  ByteReader footer(d + footer_at + kRecordHead, kFooterBody);
  const uint64_t summary_start = footer.U64();
  const uint64_t summary_offset_start = footer.U64();
  if (summary_start == 0) return;
  if (summary_start < pos_ || summary_start > footer_at) {
    notes_.push_back("its footer points outside the file: its summary was not used");
    return;
  }
  if (!SummaryCrcMatches(summary_start, footer_at)) {
    notes_.push_back("its summary section does not match its CRC: not used (the topics were "
                     "found by reading the messages)");
    return;
  }
  const size_t end = summary_offset_start > summary_start && summary_offset_start <= footer_at
                         ? static_cast<size_t>(summary_offset_start)
                         : footer_at;
  ByteReader r(d + summary_start, end - static_cast<size_t>(summary_start));
  while (r.remaining() >= kRecordHead) {
    const uint8_t op = r.U8();
    const uint64_t length = r.U64();
    if (length > r.remaining()) break;
    ParseSummaryRecord(op, r.here(), length);
    r.Skip(length);
  }
  // A channel listed before its schema gets the schema's name now.
  for (Channel& c : channels_) {
    const auto it = schemas_.find(c.schema_id);
    if (c.connection.type.empty() && it != schemas_.end()) {
      c.connection.type = it->second.name;
      c.connection.schema_encoding = it->second.encoding;
      c.connection.schema = it->second.data;
    }
  }
  has_summary_ = true;
}

bool McapFile::SummaryCrcMatches(uint64_t summary_start, size_t footer_at) const {
  const uint8_t* d = file_.data();
  const uint32_t stated = LoadLittle<uint32_t>(d + footer_at + kRecordHead + 16);
  if (stated == 0) return true;  // not computed by the writer
  // From the summary's start through the footer's summary_offset_start field.
  const size_t covered = footer_at + kRecordHead + 16 - static_cast<size_t>(summary_start);
  return Crc32(d + summary_start, covered) == stated;
}

void McapFile::ParseSummaryRecord(uint8_t op, const uint8_t* body, uint64_t length) {
  ByteReader r(body, length);
  switch (op) {
    case kMcapSchema: AddSchema(body, length); return;
    case kMcapChannel: AddChannel(body, length); return;
    case kMcapStatistics: {
      r.Skip(8 + 2 + 4 + 4 + 4 + 4);
      message_start_ns_ = r.U64();
      message_end_ns_ = r.U64();
      const uint32_t map_bytes = r.U32();
      ByteReader counts(r.here(), std::min<uint64_t>(map_bytes, r.remaining()));
      while (counts.remaining() >= 10) {
        const uint16_t channel = counts.U16();
        channel_counts_[channel] = counts.U64();
      }
      has_statistics_ = r.ok() && !channel_counts_.empty();
      return;
    }
    case kMcapChunkIndex: {
      r.Skip(8 + 8 + 8 + 8);
      r.Skip(r.U32());  // message_index_offsets
      r.Skip(8);        // message_index_length
      const std::string_view compression = r.String();
      if (r.ok()) {
        const std::optional<ChunkCodec> codec = ChunkCodecNamed(compression);
        compressions_.insert(codec ? std::string(ChunkCodecName(*codec)) : std::string(compression));
      }
      return;
    }
    default: return;
  }
}

void McapFile::AddSchema(const uint8_t* body, uint64_t length) {
  ByteReader r(body, length);
  const uint16_t id = r.U16();
  Schema s;
  s.name = r.String();
  s.encoding = r.String();
  s.data = r.String();
  if (!r.ok()) Damaged("a Schema record is shorter than its fields");
  if (id == 0) return;  // invalid by the specification: ignored
  schemas_.emplace(id, std::move(s));
}

void McapFile::AddChannel(const uint8_t* body, uint64_t length) {
  ByteReader r(body, length);
  Channel c;
  c.id = r.U16();
  c.schema_id = r.U16();
  c.connection.topic = r.String();
  c.connection.encoding = r.String();
  if (!r.ok()) Damaged("a Channel record is shorter than its fields");
  if (channel_index_[c.id] >= 0) return;  // known already (the summary's copy)
  if (c.schema_id != 0) {
    const auto it = schemas_.find(c.schema_id);
    if (it != schemas_.end()) {
      c.connection.type = it->second.name;
      c.connection.schema_encoding = it->second.encoding;
      c.connection.schema = it->second.data;
    }
  }
  channel_index_[c.id] = static_cast<int32_t>(channels_.size());
  channels_.push_back(std::move(c));
}

std::optional<std::vector<TopicSummary>> McapFile::IndexedTopics(bool /*with_counts*/) {
  if (!has_summary_ || channels_.empty()) return std::nullopt;
  std::vector<TopicSummary> topics;
  for (const Channel& c : channels_) {
    auto it = std::find_if(topics.begin(), topics.end(),
                           [&](const TopicSummary& t) { return t.name == c.connection.topic; });
    if (it == topics.end()) {
      TopicSummary t;
      t.name = c.connection.topic;
      t.type = c.connection.type;
      t.messages = has_statistics_ ? 0 : -1;
      t.first_ns = message_start_ns_;
      t.last_ns = message_end_ns_;
      topics.push_back(t);
      it = topics.end() - 1;
    }
    if (has_statistics_) {
      const auto count = channel_counts_.find(c.id);
      if (count != channel_counts_.end()) it->messages += static_cast<long long>(count->second);
    }
  }
  return topics;
}

bool McapFile::ReadBatch(MessageSink* sink) {
  const uint8_t* d = file_.data();
  const size_t size = file_.size();
  const size_t batch_start = pos_;
  while (!done_) {
    if (size - pos_ < kRecordHead) {
      if (pos_ < size)
        notes_.push_back(fmt::format("cut short at byte {} (inside a record's opcode and length): "
                                     "read up to its last whole message", size));
      else
        notes_.push_back(fmt::format("cut short at byte {} (no Data End record, no summary): "
                                     "read up to its last whole message", size));
      done_ = true;
      break;
    }
    const uint8_t op = d[pos_];
    const uint64_t length = LoadLittle<uint64_t>(d + pos_ + 1);
    const size_t body_at = pos_ + kRecordHead;
    const uint8_t* body = d + body_at;
    const uint64_t available = size - body_at;
    if (length > available) {
      chunk_offset_ = pos_;
      if (op == kMcapChunk) {
        ReadChunk(body, available, length, sink);
      } else {
        const std::string_view name = McapRecordName(op);
        notes_.push_back(fmt::format("cut short at byte {} (inside {} record at byte {}): read "
                                     "up to its last whole message", size,
                                     name.empty() ? fmt::format("an op 0x{:02x}", op)
                                                  : fmt::format("a {}", name),
                                     pos_));
      }
      done_ = true;
      break;
    }
    pos_ = body_at + static_cast<size_t>(length);
    switch (op) {
      case kMcapSchema: AddSchema(body, length); break;
      case kMcapChannel: AddChannel(body, length); break;
      case kMcapMessage: OnMessage(body, length, sink); break;
      case kMcapChunk:
        chunk_offset_ = body_at - kRecordHead;
        ReadChunk(body, length, length, sink);
        file_.ReleaseBefore(pos_);
        return true;
      case kMcapDataEnd:
      case kMcapFooter:
        done_ = true;
        break;
      default: break;  // message indexes, attachments, metadata: nothing for us
    }
    if (pos_ - batch_start >= kUnchunkedBatchBytes) break;
  }
  file_.ReleaseBefore(pos_);
  return !done_ || pos_ > batch_start;
}

void McapFile::ReadChunk(const uint8_t* body, uint64_t available, uint64_t length,
                         MessageSink* sink) {
  ++chunks_read_;
  const bool cut = available < length;
  ByteReader r(body, available);
  r.Skip(8 + 8);  // message start and end times
  const uint64_t uncompressed_size = r.U64();
  const uint32_t crc = r.U32();
  const std::string_view compression = r.String();
  const uint64_t records_length = r.U64();
  if (!r.ok()) {
    if (!cut) Damaged("its fields are shorter than the record");
    notes_.push_back(fmt::format("cut short at byte {} (inside the fields of {}): read up to its "
                                 "last whole message", file_.size(), ChunkPlace()));
    return;
  }
  const std::optional<ChunkCodec> codec = ChunkCodecNamed(compression);
  if (!codec)
    throw Error(fmt::format("{}: {} is compressed with '{}', which this reader does not know "
                            "(MCAP's are zstd and lz4)", file_.path(), ChunkPlace(),
                            detail::PrintableExcerpt(compression, 40)));
  compressions_.insert(std::string(ChunkCodecName(*codec)));
  if (!cut && records_length > r.remaining())
    Damaged("its records are longer than the record");
  const uint64_t records_available = std::min<uint64_t>(records_length, r.remaining());
  const bool records_cut = records_available < records_length;
  if (uncompressed_size > kMaxChunkBytes)
    Damaged(fmt::format("it declares {} bytes uncompressed", uncompressed_size));

  const uint8_t* records = r.here();
  size_t records_size = static_cast<size_t>(records_available);
  if (*codec != ChunkCodec::kNone) {
    if (chunk_capacity_ < uncompressed_size) {
      chunk_buffer_.reset(new uint8_t[uncompressed_size]);
      chunk_capacity_ = static_cast<size_t>(uncompressed_size);
    }
    const ChunkDecompressor::Result got =
        decompressor_.Run(*codec, records, records_size, chunk_buffer_.get(),
                          static_cast<size_t>(uncompressed_size), !records_cut);
    if (!got.error.empty() && !(records_cut && !got.complete))
      Damaged(got.error);
    if (!records_cut && !got.complete) Damaged("its compressed records end before their frame");
    if (!records_cut && got.produced != uncompressed_size)
      Damaged(fmt::format("it holds {} bytes uncompressed, not the {} it declares", got.produced,
                          uncompressed_size));
    records = chunk_buffer_.get();
    records_size = got.produced;
  } else if (!records_cut && records_size != uncompressed_size) {
    Damaged(fmt::format("it holds {} bytes, not the {} it declares", records_size,
                        uncompressed_size));
  }
  if (records_cut) {
    notes_.push_back(fmt::format("cut short at byte {} (inside {}, {} of its {} bytes there): "
                                 "read up to its last whole message", file_.size(), ChunkPlace(),
                                 records_available, records_length));
  } else if (crc != 0) {
    const uint32_t computed = Crc32(records, records_size);
    if (computed != crc)
      Damaged(fmt::format("its records' CRC-32 is {:08x}, the chunk states {:08x}", computed, crc));
  }
  ParseRecords(records, records_size, records_cut, sink);
}

void McapFile::ParseRecords(const uint8_t* data, size_t size, bool cut, MessageSink* sink) {
  size_t p = 0;
  while (p < size) {
    if (size - p < kRecordHead) {
      if (cut) return;
      Damaged("a record's opcode and length run past the chunk's end");
    }
    const uint8_t op = data[p];
    const uint64_t length = LoadLittle<uint64_t>(data + p + 1);
    p += kRecordHead;
    if (length > size - p) {
      if (cut) return;
      Damaged(fmt::format("a record of {} bytes runs past the chunk's end", length));
    }
    const uint8_t* body = data + p;
    p += static_cast<size_t>(length);
    if (op == kMcapMessage) {
      OnMessage(body, length, sink);
    } else if (op == kMcapSchema) {
      AddSchema(body, length);
    } else if (op == kMcapChannel) {
      AddChannel(body, length);
    }
  }
}

void McapFile::OnMessage(const uint8_t* body, uint64_t length, MessageSink* sink) {
  if (length < kMessageHead) Damaged("a Message record is shorter than its fields");
  const uint16_t channel_id = LoadLittle<uint16_t>(body);
  const int32_t index = channel_index_[channel_id];
  if (index < 0)
    Damaged(fmt::format("a message on channel {}, which no Channel record before it defines",
                        channel_id));
  Channel& c = channels_[static_cast<size_t>(index)];
  if (c.slot == -2) c.slot = sink->Wants(c.connection);
  if (c.slot < 0) return;
  const uint64_t log_time = LoadLittle<uint64_t>(body + 6);
  sink->OnMessage(c.slot, log_time, body + kMessageHead, static_cast<size_t>(length) - kMessageHead);
}

std::string McapFile::ChunkPlace() const {
  return fmt::format("chunk {} (at byte {})", chunks_read_, chunk_offset_);
}

void McapFile::Damaged(const std::string& what) const {
  const std::string where = chunks_read_ > 0 && chunk_offset_ > 0
                                ? ChunkPlace()
                                : fmt::format("the record before byte {}", pos_);
  throw Error(fmt::format("{}: {}: {}: the file is damaged there", file_.path(), where, what));
}

}  // namespace accelcal::bags
