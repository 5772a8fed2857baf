// A bag file mapped read-only: records are parsed where they lie (an uncompressed chunk is
// never copied) and the pages already read are let go (ReleaseBefore), so the resident memory
// stays bounded by what is being read now, whatever the file's size.
//
// Only regular files: a bag is read with random access (its index, summary and footer), so a
// pipe is refused. The size is taken at opening: a file still being written is read up to it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace accelcal::bags {

class MappedFile {
 public:
  // Throws accelcal::Error "cannot open 'PATH': <reason>" (a folder or a pipe: why it is not a
  // bag file).
  explicit MappedFile(const std::string& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  const std::string& path() const { return path_; }
  const uint8_t* data() const { return data_; }
  size_t size() const { return size_; }

  // The bytes before `offset` are not needed again: their pages leave this process's memory
  // (the system's page cache keeps them).
  void ReleaseBefore(size_t offset);

 private:
  std::string path_;
  const uint8_t* data_ = nullptr;
  size_t size_ = 0;
  size_t released_ = 0;  // bytes already let go (a multiple of the page size)
};

}  // namespace accelcal::bags
