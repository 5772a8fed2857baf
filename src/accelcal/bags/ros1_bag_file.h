// ROS 1 bags, format 2.0 (wiki.ros.org/Bags/Format/2.0: what rosbag writes since ROS C Turtle,
// and what Kalibr and most published IMU datasets use), read from the published description.
//
// Records are <header_len><header><data_len><data>, the header a run of <len>name=value fields.
// Chunks (op 0x05: uncompressed, bz2 or lz4) hold connection (0x07) and message (0x02) records;
// the index section at the bag header's index_pos lists every connection (0x07) and each
// chunk's message counts per connection (0x06). Read in file order, one chunk at a time.
//
// A bag not closed by its recorder has index_pos 0 (no index: `rosbag reindex` would rebuild
// it); it is read all the same, its connections met in the chunks. A bag cut short is read up to
// its last whole message, and Notes() says where it ends.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "accelcal/bags/bag_file.h"
#include "accelcal/bags/chunk_codec.h"
#include "accelcal/bags/mapped_file.h"

namespace accelcal::bags {

class Ros1BagFile final : public BagFile {
 public:
  // Throws accelcal::Error when the file cannot be opened or is not a ROS 1 bag of format 2.0.
  explicit Ros1BagFile(const std::string& path);

  std::string Description() const override;
  std::optional<std::vector<TopicSummary>> IndexedTopics(bool with_counts) override;
  bool ReadBatch(MessageSink* sink) override;
  std::vector<std::string> Notes() const override { return notes_; }

 private:
  struct Connection {
    BagConnection connection;
    int slot = -2;  // -2: the sink not asked yet
    long long indexed_messages = 0;
    uint64_t first_ns = 0;
    uint64_t last_ns = 0;
  };

  void ReadIndex();
  void AddConnection(std::string_view header, std::string_view data);
  void ReadChunk(std::string_view header, const uint8_t* data, size_t available, size_t length,
                 MessageSink* sink);
  void ParseRecords(const uint8_t* data, size_t size, bool cut, MessageSink* sink);
  void OnMessage(std::string_view header, const uint8_t* data, size_t size, MessageSink* sink);
  void Dispatch(std::optional<uint32_t> conn, uint64_t time_ns, const uint8_t* data, size_t size,
                MessageSink* sink);
  Connection* Find(uint32_t conn);
  [[noreturn]] void Damaged(const std::string& what) const;

  MappedFile file_;
  uint64_t index_pos_ = 0;
  bool indexed_ = false;
  std::vector<Connection> connections_;
  std::unordered_map<uint32_t, size_t> by_conn_;  // conn id -> index in connections_
  uint32_t last_conn_ = UINT32_MAX;               // the last message's connection, looked up
  size_t last_index_ = 0;
  std::set<std::string> compressions_;
  size_t pos_ = 0;  // next record
  size_t data_end_ = 0;  // where the chunks end: the index section, or the file's end
  bool done_ = false;
  long chunks_read_ = 0;
  size_t chunk_offset_ = 0;
  std::unique_ptr<uint8_t[]> chunk_buffer_;
  size_t chunk_capacity_ = 0;
  ChunkDecompressor decompressor_;
  std::vector<std::string> notes_;
};

}  // namespace accelcal::bags
