// The samples of a bag's IMU topic: the sibling of the sample reader (base/sample_reader.h) for
// ROS bags, delivering the same samples a text recording of the same data gives, through the
// same time checks and repairs (base/sample_time_check.h) in the same words.
//
// - The topic: SampleFormat::bag.topic, or the bag's only sensor_msgs/Imu topic
//   (bag_topics.h: every refusal lists the topics).
// - A sample per message: t from the header stamp (sec + nanosec * 1e-9, s), or from the bag's
//   receive time when asked (bag.receive_time) or when the first message's stamp is zero (a
//   driver that never set it: said in the summary); the three values of linear_acceleration,
//   m/s^2 by the message's definition, taken as counts of 1/counts_per_unit m/s^2 exactly as
//   `--unit m/s^2` takes a logger's converted readings (sample_format.h); no temperature.
// - t checked as a text's: a stamp that goes back, or repeats without the rounding pattern, is
//   an error naming the message ("imu.bag: /imu message 1204: t = 12.3 s does not increase
//   (message 1203 has t = 12.31 s); t must be strictly increasing"); rounded stamps are spread
//   within their step. t = message index / rate with SampleFormat::rate_hz.
// - A message that is not an Imu (a wrong size, a non-finite acceleration) is an error naming
//   it; a cut file is read up to its last whole message, and the summary says where it ends.
//
// Memory: one chunk of the bag at a time (the reader's), and the samples of that chunk.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accelcal/bags/bag_file.h"
#include "accelcal/bags/bag_topics.h"
#include "accelcal/bags/imu_message.h"
#include "accelcal/base/capture.h"
#include "accelcal/base/sample_format.h"
#include "accelcal/base/sample_reader.h"
#include "accelcal/base/sample_time_check.h"

namespace accelcal::bags {

class BagSampleStream final : private MessageSink {
 public:
  // Opens the bag at `path` and chooses its topic. `format` holds the choice (bag), the unit's
  // counts per m/s^2, the rate and the time repair; a table's options (columns, skipped rows)
  // and a unit other than m/s^2 are refused with the reason. Throws accelcal::Error.
  BagSampleStream(const std::string& path, const SampleFormat& format);
  ~BagSampleStream() override;

  // Appends the next samples (about one chunk's) to *out; false once the bag is exhausted
  // (nothing appended). Throws accelcal::InputError / Error as the header says.
  bool Next(std::vector<Sample>* out);

  // What the reading understood so far (complete once Next returned false).
  ReadingSummary Summary() const;
  // The format as read: the unit m/s^2 (with the counts per unit given or the default).
  const SampleFormat& format() const { return format_; }
  const TopicChoice& choice() const { return choice_; }

 private:
  int Wants(const BagConnection& connection) override;
  void OnMessage(int slot, uint64_t receive_time_ns, const uint8_t* data, size_t size) override;
  void Finish(std::vector<Sample>* out);
  [[noreturn]] void ThrowTimeError();

  std::string path_;
  SampleFormat format_;
  std::unique_ptr<BagFile> file_;
  std::string description_;
  TopicChoice choice_;
  bool scanned_ = false;
  std::vector<ImuEncoding> slots_;  // per wanted connection
  detail::SampleTimeCheck time_check_;
  std::vector<InputError> time_errors_;
  std::vector<Sample>* out_ = nullptr;  // during Next
  long messages_ = 0;
  bool receive_time_;
  bool stamps_absent_ = false;
  bool finished_ = false;
};

}  // namespace accelcal::bags
