// MCAP files (https://mcap.dev/spec: rosbag2's default storage since Iron, and any tool's
// recording of ROS 1 or ROS 2 messages), read from their published specification.
//
// Read in file order, record by record through the data section: chunks (uncompressed, zstd or
// lz4) one at a time, each checked against its CRC-32 when it carries one, and messages outside
// chunks. The summary section (through the footer) gives the channels, schemas and message
// counts before any message is read; a file without one (cut short, or not closed) is read all
// the same, its channels met where the data section defines them.
//
// Damage: a chunk whose CRC does not match, or whose compressed data is corrupt, stops the
// reading with an error naming the chunk and its byte offset; a file cut short (a recorder
// killed) is read up to its last whole message, and Notes() says where it ends.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "accelcal/bags/bag_file.h"
#include "accelcal/bags/chunk_codec.h"
#include "accelcal/bags/mapped_file.h"

namespace accelcal::bags {

class McapFile final : public BagFile {
 public:
  // Throws accelcal::Error when the file cannot be opened or does not start as an MCAP file.
  explicit McapFile(const std::string& path);

  std::string Description() const override;
  std::optional<std::vector<TopicSummary>> IndexedTopics(bool with_counts) override;
  bool ReadBatch(MessageSink* sink) override;
  std::vector<std::string> Notes() const override { return notes_; }

 private:
  struct Schema {
    std::string name;
    std::string encoding;
    std::string data;
  };
  struct Channel {
    uint16_t id = 0;
    uint16_t schema_id = 0;
    BagConnection connection;
    int slot = -2;  // -2: the sink not asked yet
  };

  void ReadSummary();
  bool SummaryCrcMatches(uint64_t summary_start, size_t footer_at) const;
  void ParseSummaryRecord(uint8_t op, const uint8_t* body, uint64_t length);
  void AddSchema(const uint8_t* body, uint64_t length);
  void AddChannel(const uint8_t* body, uint64_t length);
  void ReadChunk(const uint8_t* body, uint64_t available, uint64_t length, MessageSink* sink);
  // The records of a chunk (or of the data section's unchunked run). `cut`: the bytes end where
  // the file was cut, so a last partial record is the cut's, not damage.
  void ParseRecords(const uint8_t* data, size_t size, bool cut, MessageSink* sink);
  void OnMessage(const uint8_t* body, uint64_t length, MessageSink* sink);
  [[noreturn]] void Damaged(const std::string& what) const;
  std::string ChunkPlace() const;

  MappedFile file_;
  std::map<uint16_t, Schema> schemas_;
  std::vector<Channel> channels_;
  std::vector<int32_t> channel_index_;  // channel id -> index in channels_, -1: undefined
  bool has_summary_ = false;
  bool has_statistics_ = false;
  std::map<uint16_t, uint64_t> channel_counts_;  // from the Statistics record
  uint64_t message_start_ns_ = 0;
  uint64_t message_end_ns_ = 0;
  std::set<std::string> compressions_;  // of the chunks (summary's index, or those read)
  size_t pos_ = 0;        // next record of the data section
  bool done_ = false;
  long chunks_read_ = 0;
  uint64_t chunk_offset_ = 0;  // of the chunk being read, for messages
  std::unique_ptr<uint8_t[]> chunk_buffer_;
  size_t chunk_capacity_ = 0;
  ChunkDecompressor decompressor_;
  std::vector<std::string> notes_;
};

}  // namespace accelcal::bags
