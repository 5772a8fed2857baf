#include "accelcal/bags/bag_sample_stream.h"

#include <cmath>

#include <fmt/format.h>

#include "accelcal/bags/bag_open.h"
#include "accelcal/base/error.h"
#include "accelcal/base/text_scan.h"

namespace accelcal::bags {
namespace {

// The format a bag is read with: a table's options refused, the unit m/s^2.
SampleFormat BagFormat(const std::string& path, const SampleFormat& given) {
  if (given.HasExplicitLayout())
    throw Error(fmt::format("{} is a bag: its IMU messages have named fields, not columns "
                            "(--columns is for text recordings)", path));
  if (given.skip_rows > 0)
    throw Error(fmt::format("{} is a bag: --skip-rows is for text recordings", path));
  SampleFormat f = given;
  if (given.unit.kind != ReadingUnit::Kind::kMps2) {
    if (given.unit_declared)
      throw Error(fmt::format("{} is a bag: sensor_msgs/Imu's linear_acceleration is in m/s^2, and "
                              "the readings were declared in {} (--unit, or the calibration's "
                              "unit)", path, given.unit.Name()));
    f.unit = ReadingUnit{ReadingUnit::Kind::kMps2, ReadingUnit::kDefaultCountsPerUnit};
  }
  f.unit_declared = true;
  return f;
}

double SecondsOf(int64_t sec, uint32_t nsec) {
  return static_cast<double>(sec) + static_cast<double>(nsec) * 1e-9;
}

}  // namespace

BagSampleStream::BagSampleStream(const std::string& path, const SampleFormat& format)
    : path_(path),
      format_(BagFormat(path, format)),
      file_(OpenBag(path)),
      time_check_(path, format.repair_ties),
      receive_time_(format.bag.receive_time) {
  choice_ = ChooseImuTopic(path, *file_, format.bag.topic, &scanned_);
  time_check_.NameMessages(choice_.topic);
}

BagSampleStream::~BagSampleStream() = default;

int BagSampleStream::Wants(const BagConnection& c) {
  if (c.topic != choice_.topic) return -1;
  const std::string topic = detail::PrintableExcerpt(c.topic, 80);
  if (!IsImuType(c.type))
    throw Error(fmt::format("{}: topic {} holds {} messages, not sensor_msgs/Imu", path_, topic,
                            c.type.empty() ? "untyped" : detail::PrintableExcerpt(c.type, 80)));
  ImuEncoding encoding;
  std::string why;
  if (!ImuEncodingOf(c, &encoding, &why)) throw Error(fmt::format("{}: topic {}: {}", path_, topic, why));
  if (const std::string mismatch = ImuSchemaMismatch(c, encoding); !mismatch.empty())
    throw Error(fmt::format("{}: topic {} says {} but its schema is not that message's: {}",
                            path_, topic, detail::PrintableExcerpt(c.type, 80), mismatch));
  if (choice_.type.empty()) choice_.type = c.type;
  slots_.push_back(encoding);
  return static_cast<int>(slots_.size() - 1);
}

void BagSampleStream::OnMessage(int slot, uint64_t receive_time_ns, const uint8_t* data,
                                size_t size) {
  ++messages_;
  ImuReading r;
  std::string why;
  if (!DecodeImu(slots_[static_cast<size_t>(slot)], data, size, &r, &why))
    throw InputError(path_, 0, 0, fmt::format("{} message {}: {}", detail::PrintableExcerpt(choice_.topic, 80),
                                              messages_, why));
  if (messages_ == 1 && !receive_time_ && r.stamp_sec == 0 && r.stamp_nsec == 0) {
    receive_time_ = true;  // a driver that never stamped its messages
    stamps_absent_ = true;
  }
  Sample s;
  if (std::isfinite(format_.rate_hz)) {
    s.t_s = static_cast<double>(messages_ - 1) / format_.rate_hz;
  } else if (receive_time_) {
    s.t_s = SecondsOf(static_cast<int64_t>(receive_time_ns / 1000000000u),
                      static_cast<uint32_t>(receive_time_ns % 1000000000u));
  } else {
    s.t_s = SecondsOf(r.stamp_sec, r.stamp_nsec);
  }
  const double k = format_.unit.counts_per_unit;
  s.raw_counts = Eigen::Vector3d(r.linear_acceleration[0] * k, r.linear_acceleration[1] * k,
                                 r.linear_acceleration[2] * k);
  time_check_.Add(s, {}, messages_, 0, out_, &time_errors_);
  if (!time_errors_.empty()) ThrowTimeError();
}

void BagSampleStream::ThrowTimeError() {
  const InputError e = time_errors_.front();
  if (receive_time_ || std::isfinite(format_.rate_hz)) throw e;
  // The stamps are the driver's: the bag's own receive times may still be in order.
  throw InputError(e.file(), e.line(), e.column(),
                   e.message() + " (the header stamps; --bag-time receive reads the bag's receive times)");
}

bool BagSampleStream::Next(std::vector<Sample>* out) {
  const size_t before = out->size();
  out_ = out;
  while (out->size() == before && !finished_) {
    if (!file_->ReadBatch(this)) Finish(out);
  }
  out_ = nullptr;
  return out->size() > before;
}

void BagSampleStream::Finish(std::vector<Sample>* out) {
  finished_ = true;
  time_check_.Finish(out, &time_errors_);
  if (!time_errors_.empty()) ThrowTimeError();
  if (messages_ == 0) throw Error(NoMessagesOn(path_, choice_.topic, ListTopics(path_)));
}

ReadingSummary BagSampleStream::Summary() const {
  ReadingSummary s;
  s.source_name = path_;
  s.origin = fmt::format("topic {} ({}); {}", detail::PrintableExcerpt(choice_.topic, 80),
                         choice_.type.empty() ? "sensor_msgs/Imu" : choice_.type, file_->Description());
  s.columns = "linear_acceleration x y z";
  s.time_source = stamps_absent_ ? "t from the bag's receive times (the messages' header stamps are zero)"
                  : receive_time_ ? "t from the bag's receive times (--bag-time receive)"
                                  : "t from the header stamps";
  s.data_rows = messages_;
  s.samples = time_check_.delivered();
  s.rate_hz = format_.rate_hz;
  s.median_interval_s = time_check_.MedianIntervalS();
  s.repaired_ties = time_check_.repaired();
  s.stamp_step_s = time_check_.stamp_step_s();
  s.unit = format_.unit;
  if (scanned_) s.notes.push_back("read twice (once for its topics: it has no index)");
  for (const std::string& n : file_->Notes()) s.notes.push_back(n);
  return s;
}

}  // namespace accelcal::bags
