#include "accelcal/io/recording_stream.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "accelcal/bags/bag_open.h"
#include "accelcal/base/error.h"

namespace accelcal {
namespace {

std::string StreamFailure(const char* what, const std::string& path, int err) {
  return std::string(what) + " '" + path + "': " + std::strerror(err);
}

}  // namespace

RecordingStream::RecordingStream(const std::string& path, size_t block_bytes,
                                 const SampleFormat& format)
    : path_(path),
      block_bytes_(block_bytes),
      reader_(path, format, SampleReader::OnMalformed::kThrow),
      reader_unit_(format.unit) {
  if (block_bytes_ == 0) throw Error("RecordingStream: block_bytes must be > 0");
  if (bags::DetectBag(path)) {
    bag_ = std::make_unique<bags::BagSampleStream>(path, format);
    return;
  }
  if (!format.bag.topic.empty())
    throw Error(fmt::format("--topic {}: {} is not a bag (ROS 1 .bag, .mcap, .db3, or a ROS 2 bag "
                            "folder)", format.bag.topic, path));
  if (format.bag.receive_time)
    throw Error(fmt::format("--bag-time: {} is not a bag (ROS 1 .bag, .mcap, .db3, or a ROS 2 bag "
                            "folder)", path));
  if (path == "-") {
    fd_ = STDIN_FILENO;
  } else {
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) throw Error(StreamFailure("cannot open", path, errno));
    owns_fd_ = true;
  }
  struct stat info {};
  if (::fstat(fd_, &info) == 0) {
    if (S_ISDIR(info.st_mode)) {
      if (owns_fd_) ::close(fd_);
      throw Error(StreamFailure("cannot open", path, EISDIR));
    }
    if (S_ISREG(info.st_mode) && info.st_size > 0) size_hint_ = static_cast<size_t>(info.st_size);
  }
  // A partial line is at most the line limit (and its CR LF); a block goes after it.
  capacity_ = static_cast<size_t>(format.max_line_bytes) + 2 + block_bytes_;
  buffer_.reset(new char[capacity_]);
}

RecordingStream::~RecordingStream() {
  if (owns_fd_ && fd_ >= 0) ::close(fd_);
}

bool RecordingStream::Fill() {
  if (at_eof_) return false;
  size_t got_total = 0;
  while (got_total < block_bytes_) {
    const ssize_t got = ::read(fd_, buffer_.get() + used_, block_bytes_ - got_total);
    if (got < 0) {
      if (errno == EINTR) continue;
      throw Error(StreamFailure("cannot read", path_, errno));
    }
    if (got == 0) {
      at_eof_ = true;
      break;
    }
    used_ += static_cast<size_t>(got);
    got_total += static_cast<size_t>(got);
    if (size_hint_ == 0) break;  // a pipe: take what came, do not wait for a full block
  }
  bytes_read_ += got_total;
  return got_total > 0;
}

bool RecordingStream::Next(std::vector<Sample>* samples) {
  samples->clear();
  return AppendNext(samples);
}

bool RecordingStream::AppendNext(std::vector<Sample>* samples) {
  if (bag_) return bag_->Next(samples);
  const size_t before = samples->size();
  // Read until at least one sample is parsed or the file ends (a block may hold only comments,
  // or only part of one long line).
  while (samples->size() == before && !finished_) {
    Fill();
    const size_t consumed =
        reader_.Consume(std::string_view(buffer_.get(), used_), at_eof_, samples);
    used_ -= consumed;
    if (used_ > 0 && consumed > 0) std::memmove(buffer_.get(), buffer_.get() + consumed, used_);
    if (at_eof_) {
      reader_.Finish(samples);
      finished_ = true;
    }
  }
  return samples->size() > before;
}

}  // namespace accelcal
