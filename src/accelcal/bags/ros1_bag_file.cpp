#include "accelcal/bags/ros1_bag_file.h"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "accelcal/bags/byte_reader.h"
#include "accelcal/base/error.h"
#include "accelcal/base/text_scan.h"

namespace accelcal::bags {
namespace {

constexpr std::string_view kRos1Magic = "#ROSBAG V2.0\n";

enum Ros1Op : uint8_t {
  kRos1MessageData = 0x02,
  kRos1BagHeader = 0x03,
  kRos1IndexData = 0x04,
  kRos1Chunk = 0x05,
  kRos1ChunkInfo = 0x06,
  kRos1Connection = 0x07,
};

// A chunk that declares more than this uncompressed is taken for damage, not allocated.
constexpr uint64_t kMaxRos1ChunkBytes = uint64_t{1} << 32;

// The fields of a record header (or of a connection's header), name=value each.
class FieldReader {
 public:
  explicit FieldReader(std::string_view header) : rest_(header) {}
  // False at the end, or when a field's length runs past the header (ok() then false).
  bool Next(std::string_view* name, std::string_view* value) {
    if (rest_.empty()) return false;
    if (rest_.size() < 4) return Fail();
    const uint32_t len = LoadLittle<uint32_t>(reinterpret_cast<const uint8_t*>(rest_.data()));
    if (len > rest_.size() - 4) return Fail();
    const std::string_view field = rest_.substr(4, len);
    rest_.remove_prefix(4 + static_cast<size_t>(len));
    const size_t eq = field.find('=');
    if (eq == std::string_view::npos) return Fail();
    *name = field.substr(0, eq);
    *value = field.substr(eq + 1);
    return true;
  }
  bool ok() const { return ok_; }

 private:
  bool Fail() {
    ok_ = false;
    rest_ = {};
    return false;
  }
  std::string_view rest_;
  bool ok_ = true;
};

// A field's value as an integer of its width (little-endian), or nullopt for a wrong width.
template <typename T>
std::optional<T> FieldValue(std::string_view value) {
  if (value.size() != sizeof(T)) return std::nullopt;
  return LoadLittle<T>(reinterpret_cast<const uint8_t*>(value.data()));
}

// ROS time (uint32 seconds, uint32 nanoseconds) as ns.
uint64_t Ros1TimeNs(std::string_view value) {
  if (value.size() != 8) return 0;
  const auto* p = reinterpret_cast<const uint8_t*>(value.data());
  return uint64_t{LoadLittle<uint32_t>(p)} * 1000000000u + LoadLittle<uint32_t>(p + 4);
}

std::optional<uint8_t> OpOf(std::string_view header) {
  FieldReader f(header);
  std::string_view name, value;
  while (f.Next(&name, &value))
    if (name == "op" && value.size() == 1) return static_cast<uint8_t>(value[0]);
  return std::nullopt;
}

// One record at `p` of a span of `size` bytes: its header, and its data as far as it is there.
struct Ros1Record {
  std::string_view header;
  const uint8_t* data = nullptr;
  size_t data_length = 0;     // declared
  size_t data_available = 0;  // present
  size_t total = 0;           // bytes of the whole record (when complete)
  bool head_complete = false; // header_len, header and data_len are all there
};

Ros1Record RecordAt(const uint8_t* p, size_t size) {
  Ros1Record r;
  if (size < 4) return r;
  const uint32_t header_len = LoadLittle<uint32_t>(p);
  if (header_len > size - 4 || size - 4 - header_len < 4) return r;
  r.header = std::string_view(reinterpret_cast<const char*>(p + 4), header_len);
  const uint32_t data_len = LoadLittle<uint32_t>(p + 4 + header_len);
  r.data = p + 8 + header_len;
  r.data_length = data_len;
  r.data_available = std::min<size_t>(data_len, size - 8 - header_len);
  r.total = 8 + size_t{header_len} + data_len;
  r.head_complete = true;
  return r;
}

}  // namespace

Ros1BagFile::Ros1BagFile(const std::string& path) : file_(path) {
  const auto* d = reinterpret_cast<const char*>(file_.data());
  const std::string_view start(d, std::min(file_.size(), kRos1Magic.size()));
  if (start != kRos1Magic) {
    if (start.substr(0, 9) == "#ROSBAG V" || start.substr(0, 10) == "#ROSRECORD") {
      const std::string_view first_line(d, std::min<size_t>(file_.size(), 20));
      throw Error(fmt::format("{}: a ROS bag of format '{}': only format 2.0 is read (`rosbag "
                              "fix` converts older ones)", file_.path(),
                              detail::PrintableExcerpt(first_line.substr(0, first_line.find('\n')), 20)));
    }
    throw Error(fmt::format("{}: not a ROS 1 bag (it does not start with '#ROSBAG V2.0')",
                            file_.path()));
  }
  pos_ = kRos1Magic.size();
  const Ros1Record header = RecordAt(file_.data() + pos_, file_.size() - pos_);
  if (!header.head_complete || OpOf(header.header) != kRos1BagHeader)
    throw Error(fmt::format("{}: its bag header record is missing or cut", file_.path()));
  FieldReader f(header.header);
  std::string_view name, value;
  while (f.Next(&name, &value))
    if (name == "index_pos") index_pos_ = FieldValue<uint64_t>(value).value_or(0);
  pos_ += std::min(header.total, file_.size() - pos_);
  data_end_ = file_.size();
  ReadIndex();
}

std::string Ros1BagFile::Description() const {
  std::string out = "ROS 1 bag";
  std::string codecs;
  for (const std::string& c : compressions_) codecs += (codecs.empty() ? "" : " and ") + c;
  if (!codecs.empty()) out += ", " + codecs + " chunks";
  return out;
}

// The index section: every connection, and each chunk's message count per connection.
void Ros1BagFile::ReadIndex() {
  if (index_pos_ == 0) {
    notes_.push_back("it has no index (its recorder did not close it: `rosbag reindex` rebuilds "
                     "one); its messages were read all the same");
    return;
  }
  if (index_pos_ < pos_ || index_pos_ >= file_.size()) {
    notes_.push_back(fmt::format("its index is said to start at byte {}, past its end (cut "
                                 "short?); its messages were read all the same", index_pos_));
    return;
  }
  data_end_ = static_cast<size_t>(index_pos_);
  size_t p = data_end_;
  std::map<uint32_t, std::pair<long long, std::pair<uint64_t, uint64_t>>> per_conn;
  while (p < file_.size()) {
    const Ros1Record r = RecordAt(file_.data() + p, file_.size() - p);
    if (!r.head_complete || r.data_available < r.data_length) {
      notes_.push_back("its index is cut short: the topics were found by reading");
      connections_.clear();
      by_conn_.clear();
      return;
    }
    const std::optional<uint8_t> op = OpOf(r.header);
    if (op == kRos1Connection) {
      AddConnection(r.header, std::string_view(reinterpret_cast<const char*>(r.data), r.data_length));
    } else if (op == kRos1ChunkInfo) {
      FieldReader f(r.header);
      std::string_view name, value;
      uint64_t start = 0, end = 0;
      while (f.Next(&name, &value)) {
        if (name == "start_time") start = Ros1TimeNs(value);
        if (name == "end_time") end = Ros1TimeNs(value);
      }
      ByteReader counts(r.data, r.data_length);
      while (counts.remaining() >= 8) {
        const uint32_t conn = counts.U32();
        auto& entry = per_conn[conn];
        entry.first += counts.U32();
        if (entry.second.first == 0 || start < entry.second.first) entry.second.first = start;
        entry.second.second = std::max(entry.second.second, end);
      }
    }
    p += r.total;
  }
  for (const auto& [conn, entry] : per_conn) {
    if (Connection* c = Find(conn)) {
      c->indexed_messages = entry.first;
      c->first_ns = entry.second.first;
      c->last_ns = entry.second.second;
    }
  }
  indexed_ = true;
}

void Ros1BagFile::AddConnection(std::string_view header, std::string_view data) {
  FieldReader f(header);
  std::string_view name, value;
  std::optional<uint32_t> conn;
  Connection c;
  while (f.Next(&name, &value)) {
    if (name == "conn") conn = FieldValue<uint32_t>(value);
    if (name == "topic") c.connection.topic = value;
  }
  if (!conn) Damaged("a connection record has no conn field");
  if (by_conn_.count(*conn) > 0) return;
  FieldReader g(data);
  while (g.Next(&name, &value)) {
    if (name == "type") c.connection.type = value;
    if (name == "md5sum") c.connection.md5sum = value;
    if (name == "message_definition") c.connection.schema = value;
    if (name == "topic" && c.connection.topic.empty()) c.connection.topic = value;
  }
  c.connection.encoding = "ros1";
  c.connection.schema_encoding = c.connection.schema.empty() ? "" : "ros1msg";
  by_conn_[*conn] = connections_.size();
  connections_.push_back(std::move(c));
  last_conn_ = UINT32_MAX;
}

Ros1BagFile::Connection* Ros1BagFile::Find(uint32_t conn) {
  if (conn == last_conn_) return &connections_[last_index_];
  const auto it = by_conn_.find(conn);
  if (it == by_conn_.end()) return nullptr;
  last_conn_ = conn;
  last_index_ = it->second;
  return &connections_[it->second];
}

std::optional<std::vector<TopicSummary>> Ros1BagFile::IndexedTopics(bool /*with_counts*/) {
  if (!indexed_) return std::nullopt;
  std::vector<TopicSummary> topics;
  for (const Connection& c : connections_) {
    auto it = std::find_if(topics.begin(), topics.end(),
                           [&](const TopicSummary& t) { return t.name == c.connection.topic; });
    if (it == topics.end()) {
      topics.push_back({c.connection.topic, c.connection.type, 0, c.first_ns, c.last_ns});
      it = topics.end() - 1;
    } else {
      if (c.first_ns != 0 && (it->first_ns == 0 || c.first_ns < it->first_ns)) it->first_ns = c.first_ns;
      it->last_ns = std::max(it->last_ns, c.last_ns);
    }
    it->messages += c.indexed_messages;
  }
  return topics;
}

bool Ros1BagFile::ReadBatch(MessageSink* sink) {
  const size_t batch_start = pos_;
  while (!done_) {
    if (pos_ >= data_end_) {
      done_ = true;
      break;
    }
    const Ros1Record r = RecordAt(file_.data() + pos_, data_end_ - pos_);
    if (!r.head_complete) {
      notes_.push_back(fmt::format("cut short at byte {} (inside a record's header): read up to "
                                   "its last whole message", data_end_));
      done_ = true;
      break;
    }
    const std::optional<uint8_t> op = OpOf(r.header);
    const bool cut = r.data_available < r.data_length;
    if (op == kRos1Chunk) {
      chunk_offset_ = pos_;
      ++chunks_read_;
      ReadChunk(r.header, r.data, r.data_available, r.data_length, sink);
      if (cut) {
        done_ = true;
        break;
      }
      pos_ += r.total;
      file_.ReleaseBefore(pos_);
      return true;
    }
    if (cut) {
      notes_.push_back(fmt::format("cut short at byte {} (inside the record at byte {}): read "
                                   "up to its last whole message", data_end_, pos_));
      done_ = true;
      break;
    }
    if (op == kRos1Connection) {
      AddConnection(r.header, std::string_view(reinterpret_cast<const char*>(r.data), r.data_length));
    } else if (op == kRos1MessageData) {
      OnMessage(r.header, r.data, r.data_length, sink);
    } else if (op == kRos1ChunkInfo) {
      done_ = true;  // the index section of a bag whose index_pos was not written
      break;
    }
    pos_ += r.total;
  }
  file_.ReleaseBefore(pos_);
  return !done_ || pos_ > batch_start;
}

void Ros1BagFile::ReadChunk(std::string_view header, const uint8_t* data, size_t available,
                            size_t length, MessageSink* sink) {
  FieldReader f(header);
  std::string_view name, value;
  std::string compression = "none";
  std::optional<uint32_t> size;
  while (f.Next(&name, &value)) {
    if (name == "compression") compression = value;
    if (name == "size") size = FieldValue<uint32_t>(value);
  }
  const std::optional<ChunkCodec> codec = ChunkCodecNamed(compression);
  if (!codec || *codec == ChunkCodec::kZstd)
    throw Error(fmt::format("{}: chunk {} (at byte {}) is compressed with '{}', which ROS 1 bags "
                            "do not use (none, bz2, lz4)", file_.path(), chunks_read_,
                            chunk_offset_, detail::PrintableExcerpt(compression, 40)));
  compressions_.insert(std::string(ChunkCodecName(*codec)));
  const bool cut = available < length;
  const size_t uncompressed = size ? *size : length;
  if (uncompressed > kMaxRos1ChunkBytes) Damaged(fmt::format("it declares {} bytes", uncompressed));
  const uint8_t* records = data;
  size_t records_size = available;
  if (*codec != ChunkCodec::kNone) {
    if (!size) Damaged("a compressed chunk without its size");
    if (chunk_capacity_ < uncompressed) {
      chunk_buffer_.reset(new uint8_t[uncompressed]);
      chunk_capacity_ = uncompressed;
    }
    const ChunkDecompressor::Result got =
        decompressor_.Run(*codec, data, available, chunk_buffer_.get(), uncompressed, !cut);
    if (!cut && (!got.error.empty() || !got.complete || got.produced != uncompressed))
      Damaged(!got.error.empty() ? got.error
                                 : fmt::format("it holds {} bytes uncompressed, not the {} it "
                                               "declares", got.produced, uncompressed));
    records = chunk_buffer_.get();
    records_size = got.produced;
  } else if (!cut && size && *size != length) {
    Damaged(fmt::format("it holds {} bytes, not the {} it declares", length, *size));
  }
  if (cut)
    notes_.push_back(fmt::format("cut short at byte {} (inside chunk {} at byte {}, {} of its {} "
                                 "bytes there): read up to its last whole message", data_end_,
                                 chunks_read_, chunk_offset_, available, length));
  ParseRecords(records, records_size, cut, sink);
}

void Ros1BagFile::ParseRecords(const uint8_t* data, size_t size, bool cut, MessageSink* sink) {
  size_t p = 0;
  while (p < size) {
    const Ros1Record r = RecordAt(data + p, size - p);
    if (!r.head_complete || r.data_available < r.data_length) {
      if (cut) return;
      Damaged("a record runs past the chunk's end");
    }
    // One pass over the header's fields: the op, and a message's connection and time.
    FieldReader f(r.header);
    std::string_view name, value;
    uint8_t op = 0;
    std::optional<uint32_t> conn;
    uint64_t time_ns = 0;
    while (f.Next(&name, &value)) {
      if (name == "op" && value.size() == 1) op = static_cast<uint8_t>(value[0]);
      else if (name == "conn") conn = FieldValue<uint32_t>(value);
      else if (name == "time") time_ns = Ros1TimeNs(value);
    }
    if (op == kRos1MessageData) {
      Dispatch(conn, time_ns, r.data, r.data_length, sink);
    } else if (op == kRos1Connection) {
      AddConnection(r.header, std::string_view(reinterpret_cast<const char*>(r.data), r.data_length));
    }
    p += r.total;
  }
}

void Ros1BagFile::OnMessage(std::string_view header, const uint8_t* data, size_t size,
                            MessageSink* sink) {
  FieldReader f(header);
  std::string_view name, value;
  std::optional<uint32_t> conn;
  uint64_t time_ns = 0;
  while (f.Next(&name, &value)) {
    if (name == "conn") conn = FieldValue<uint32_t>(value);
    else if (name == "time") time_ns = Ros1TimeNs(value);
  }
  Dispatch(conn, time_ns, data, size, sink);
}

void Ros1BagFile::Dispatch(std::optional<uint32_t> conn, uint64_t time_ns, const uint8_t* data,
                           size_t size, MessageSink* sink) {
  if (!conn) Damaged("a message record has no conn field");
  Connection* c = Find(*conn);
  if (c == nullptr)
    Damaged(fmt::format("a message on connection {}, which no connection record before it "
                        "defines", *conn));
  if (c->slot == -2) c->slot = sink->Wants(c->connection);
  if (c->slot < 0) return;
  sink->OnMessage(c->slot, time_ns, data, size);
}

void Ros1BagFile::Damaged(const std::string& what) const {
  const std::string where = chunks_read_ > 0 ? fmt::format("chunk {} (at byte {})", chunks_read_, chunk_offset_)
                                             : fmt::format("the record at byte {}", pos_);
  throw Error(fmt::format("{}: {}: {}: the file is damaged there", file_.path(), where, what));
}

}  // namespace accelcal::bags
