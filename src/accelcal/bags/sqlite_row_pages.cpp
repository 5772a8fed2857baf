#include "accelcal/bags/sqlite_row_pages.h"

#include <algorithm>
#include <cstring>

namespace accelcal::bags {
namespace {

constexpr uint8_t kInteriorTablePage = 0x05;
constexpr uint8_t kLeafTablePage = 0x0D;
// Deeper than any real table b-tree (a 64 KiB-page tree of depth 20 would hold more rows than
// a file can): a deeper one is a loop in a damaged file.
constexpr size_t kMaxDepth = 40;
// How many cells after the one being read are fetched into the cache ahead (1, 2 and 4
// measured: 4 the fastest).
constexpr uint32_t kCellsAhead = 4;

uint32_t Big16(const uint8_t* p) { return static_cast<uint32_t>(p[0]) << 8 | p[1]; }
uint32_t Big32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) << 24 | static_cast<uint32_t>(p[1]) << 16 |
         static_cast<uint32_t>(p[2]) << 8 | p[3];
}

// SQLite's varint (1 to 9 bytes, big-endian groups of 7 bits, the ninth byte whole); false when
// it runs past `end`.
bool Varint(const uint8_t** p, const uint8_t* end, uint64_t* out) {
  uint64_t v = 0;
  for (int i = 0; i < 8; ++i) {
    if (*p >= end) return false;
    const uint8_t b = *(*p)++;
    v = v << 7 | (b & 0x7f);
    if ((b & 0x80) == 0) {
      *out = v;
      return true;
    }
  }
  if (*p >= end) return false;
  *out = v << 8 | *(*p)++;
  return true;
}

// A record's integer serial types (1-6: big-endian two's complement of 1, 2, 3, 4, 6, 8 bytes;
// 8 and 9: the constants 0 and 1): its size in bytes, or -1 for a value that is not an integer.
int IntegerBytes(uint64_t serial_type) {
  static constexpr int kBytes[] = {-1, 1, 2, 3, 4, 6, 8, -1, 0, 0};
  return serial_type < 10 ? kBytes[serial_type] : -1;
}

int64_t IntegerValue(const uint8_t* p, uint64_t serial_type, int bytes) {
  if (serial_type == 8 || serial_type == 9) return static_cast<int64_t>(serial_type - 8);
  uint64_t v = (p[0] & 0x80) != 0 ? ~uint64_t{0} : 0;  // sign-extended
  for (int i = 0; i < bytes; ++i) v = v << 8 | p[i];
  return static_cast<int64_t>(v);
}

}  // namespace

std::optional<SqliteRowPages> SqliteRowPages::Open(MappedFile* file, uint32_t root_page,
                                                   std::vector<int64_t> wanted_topic_ids) {
  const uint8_t* h = file->data();
  if (file->size() < 100 || std::memcmp(h, "SQLite format 3", 16) != 0) return std::nullopt;
  size_t page_bytes = Big16(h + 16);
  if (page_bytes == 1) page_bytes = 65536;
  if (page_bytes < 512 || page_bytes > 65536 || (page_bytes & (page_bytes - 1)) != 0) return std::nullopt;
  const size_t usable = page_bytes - h[20];
  // The payload fractions are fixed at 64, 32, 32 by the format.
  if (usable < 480 || h[18] < 1 || h[18] > 2 || h[21] != 64 || h[22] != 32 || h[23] != 32)
    return std::nullopt;
  SqliteRowPages scan(file, root_page, std::move(wanted_topic_ids));
  scan.page_bytes_ = page_bytes;
  scan.usable_bytes_ = usable;
  scan.pages_ = static_cast<uint32_t>(std::min<size_t>(file->size() / page_bytes, UINT32_MAX));
  scan.read_version_ = h[18];
  return scan;
}

SqliteRowPages::SqliteRowPages(MappedFile* file, uint32_t root_page, std::vector<int64_t> wanted)
    : file_(file), root_page_(root_page), wanted_(std::move(wanted)), interior_copies_(kMaxDepth) {}

bool SqliteRowPages::Stop() {
  stopped_ = true;
  return false;
}

// Enters a page (checked as SQLite checks a page it enters: its type, its cell count within the
// page, its cell content area after the cell pointers).
bool SqliteRowPages::Push(uint32_t page_number) {
  if (page_number < 2 || page_number > pages_ || stack_.size() >= kMaxDepth) return Stop();
  const size_t at = (page_number - size_t{1}) * page_bytes_;
  Frame f;
  f.page = file_->data() + at;
  f.header = f.page;
  if (f.header[0] != kLeafTablePage && f.header[0] != kInteriorTablePage) return Stop();
  f.leaf = f.header[0] == kLeafTablePage;
  f.cells = Big16(f.header + 3);
  const size_t cells_end = (f.leaf ? 8 : 12) + 2 * size_t{f.cells};
  size_t content = Big16(f.header + 5);
  if (content == 0) content = 65536;
  if (cells_end > content || content > usable_bytes_) return Stop();
  if (f.leaf) {
    file_->ReleaseBefore(at);  // leaves come in file order in a table written in order
  } else {
    // An interior page is read again at each of its children: read from a copy, so that the
    // pages let go behind the leaves are not mapped back in around it (the kernel maps a
    // page's neighbours with it).
    std::vector<uint8_t>& copy = interior_copies_[stack_.size()];
    copy.assign(f.page, f.page + usable_bytes_);
    f.page = f.header = copy.data();
  }
  stack_.push_back(f);
  return true;
}

bool SqliteRowPages::Next(Row* row) {
  if (stopped_) return false;
  if (!started_) {
    started_ = true;
    if (!Push(root_page_)) return false;
  }
  while (!stack_.empty()) {
    Frame& f = stack_.back();
    if (f.leaf) {
      while (f.next < f.cells) {
        // A cell is read once, and waiting for it to come from memory was most of the time per
        // row (140 -> 95 ns a row on the 8-hour bench bag): the next kCellsAhead are fetched
        // ahead (again at each cell: a leaf's first cells are fetched ahead too).
        for (uint32_t ahead = f.next + 1; ahead <= f.next + kCellsAhead && ahead < f.cells; ++ahead)
          __builtin_prefetch(f.page + std::min<size_t>(Big16(f.header + 8 + 2 * size_t{ahead}), usable_bytes_ - 1));
        bool skip = false;
        if (ReadCell(f, f.next++, row, &skip)) return true;
        if (!skip) return false;
      }
      stack_.pop_back();
      continue;
    }
    if (f.next > f.cells) {
      stack_.pop_back();
      continue;
    }
    uint32_t child;
    if (f.next < f.cells) {
      const size_t cell = Big16(f.header + 12 + 2 * size_t{f.next});
      if (cell < 12 + 2 * size_t{f.cells} || cell + 4 > usable_bytes_) return Stop();
      child = Big32(f.page + cell);
    } else {
      child = Big32(f.header + 8);  // the right-most child
    }
    ++f.next;
    if (!Push(child)) return false;
  }
  return false;
}

bool SqliteRowPages::ReadCell(const Frame& leaf, uint32_t cell, Row* row, bool* skip) {
  const size_t at = Big16(leaf.header + 8 + 2 * size_t{cell});
  if (at < 8 + 2 * size_t{leaf.cells} || at >= usable_bytes_) return Stop();
  const uint8_t* p = leaf.page + at;
  const uint8_t* const page_end = leaf.page + usable_bytes_;
  uint64_t payload_bytes = 0;
  uint64_t rowid_bits = 0;
  if (!Varint(&p, page_end, &payload_bytes) || !Varint(&p, page_end, &rowid_bits)) return Stop();
  const auto rowid = static_cast<int64_t>(rowid_bits);
  if (read_any_ && rowid <= last_rowid_) return Stop();
  // How much of the payload lies on this page (the format's rule); the rest on overflow pages.
  const size_t usable = usable_bytes_;
  const size_t max_local = usable - 35;
  size_t local = 0;
  if (payload_bytes <= max_local) {
    local = static_cast<size_t>(payload_bytes);
  } else {
    const size_t min_local = (usable - 12) * 32 / 255 - 23;
    const size_t k = min_local + static_cast<size_t>((payload_bytes - min_local) % (usable - 4));
    local = k <= max_local ? k : min_local;
  }
  const bool overflows = local < payload_bytes;
  if (static_cast<size_t>(page_end - p) < local + (overflows ? 4 : 0)) return Stop();
  // The record: its header (size, then the four columns' serial types), then the values.
  const uint8_t* h = p;
  const uint8_t* const local_end = p + local;
  uint64_t header_bytes = 0;
  uint64_t types[4];
  if (!Varint(&h, local_end, &header_bytes) || header_bytes > local) return Stop();
  const uint8_t* const header_end = p + header_bytes;
  for (uint64_t& t : types)
    if (!Varint(&h, header_end, &t)) return Stop();
  // Exactly four columns; id NULL (the rowid stands for it); two integers; a blob.
  const int topic_bytes = IntegerBytes(types[1]);
  const int time_bytes = IntegerBytes(types[2]);
  if (h != header_end || types[0] != 0 || topic_bytes < 0 || time_bytes < 0 || types[3] < 12 ||
      types[3] % 2 != 0)
    return Stop();
  const size_t data_offset = static_cast<size_t>(header_bytes) + static_cast<size_t>(topic_bytes + time_bytes);
  const uint64_t data_size = (types[3] - 12) / 2;
  if (data_offset > local || data_offset + data_size > payload_bytes) return Stop();
  const int64_t topic_id = IntegerValue(p + header_bytes, types[1], topic_bytes);
  if (std::find(wanted_.begin(), wanted_.end(), topic_id) == wanted_.end()) {
    read_any_ = true;
    last_rowid_ = rowid;
    *skip = true;
    return false;
  }
  const uint8_t* payload = p;
  if (overflows && !Assemble(p, local, payload_bytes, Big32(p + local), &payload)) return Stop();
  row->rowid = rowid;
  row->topic_id = topic_id;
  row->timestamp = IntegerValue(p + header_bytes + topic_bytes, types[2], time_bytes);
  row->data = payload + data_offset;
  row->size = static_cast<size_t>(data_size);
  read_any_ = true;
  last_rowid_ = rowid;
  return true;
}

// A payload that runs onto overflow pages, gathered into one buffer: its first `local` bytes,
// then each overflow page's (a 4-byte next page number, then usable - 4 bytes of payload).
bool SqliteRowPages::Assemble(const uint8_t* local_bytes, size_t local, uint64_t payload_bytes,
                              uint32_t first_overflow, const uint8_t** payload) {
  if (payload_bytes > file_->size()) return false;
  assembled_.assign(local_bytes, local_bytes + local);
  uint32_t page = first_overflow;
  while (assembled_.size() < payload_bytes) {
    if (page < 2 || page > pages_) return false;
    const uint8_t* at = file_->data() + (page - size_t{1}) * page_bytes_;
    const size_t take = std::min<size_t>(usable_bytes_ - 4, static_cast<size_t>(payload_bytes) - assembled_.size());
    assembled_.insert(assembled_.end(), at + 4, at + 4 + take);
    page = Big32(at);
  }
  *payload = assembled_.data();
  return true;
}

}  // namespace accelcal::bags
