#include "accelcal/io/recording_stream.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "accelcal/base/error.h"
#include "accelcal/io/recording_reader.h"

namespace accelcal {
namespace {

std::string WriteTemp(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::vector<Sample> ReadAll(const std::string& path, size_t block_bytes) {
  RecordingStream stream(path, block_bytes);
  std::vector<Sample> all, chunk;
  while (stream.Next(&chunk)) {
    EXPECT_FALSE(chunk.empty());
    all.insert(all.end(), chunk.begin(), chunk.end());
  }
  EXPECT_TRUE(chunk.empty());
  EXPECT_FALSE(stream.Next(&chunk));  // stays exhausted
  return all;
}

TEST(RecordingStream, SameSamplesAsTheWholeFileReaderWhateverTheBlockSize) {
  std::string text = "\xEF\xBB\xBF# header\r\n\n";
  for (int i = 0; i < 500; ++i)
    text += std::to_string(i * 0.01) + (i % 3 ? ", " : "\t") + std::to_string(2000 + i % 7) + " " +
            std::to_string(-i) + " 4095.5 " + std::to_string(24.0 + i * 1e-3) + (i % 5 ? "\n" : "\r\n");
  text += "# a comment in the middle\n5.0 1 2 3 25";  // no final newline
  const std::string path = WriteTemp("accelcal_stream_test.txt", text);
  const std::vector<Sample> whole = ParseRecording(text, path);
  ASSERT_EQ(whole.size(), 501u);
  for (const size_t block : {size_t{1}, size_t{7}, size_t{64}, size_t{4096}, size_t{1} << 22}) {
    const std::vector<Sample> streamed = ReadAll(path, block);
    ASSERT_EQ(streamed.size(), whole.size()) << "block " << block;
    for (size_t i = 0; i < whole.size(); ++i) {
      EXPECT_EQ(streamed[i].t_s, whole[i].t_s);
      EXPECT_EQ(streamed[i].raw_counts, whole[i].raw_counts);
      EXPECT_EQ(streamed[i].temp_c, whole[i].temp_c);
    }
  }
}

TEST(RecordingStream, ErrorsNameTheSameLineAsTheWholeFileReader) {
  const std::string text = "0 1 2 3\n0.1 1 2 3\n0.2 1 x 3\n0.3 1 2 3\n";
  const std::string path = WriteTemp("accelcal_stream_bad.txt", text);
  std::string expected;
  try {
    ParseRecording(text, path);
  } catch (const InputError& e) {
    expected = e.what();
  }
  ASSERT_FALSE(expected.empty());
  for (const size_t block : {size_t{3}, size_t{4096}}) {
    RecordingStream stream(path, block);
    std::vector<Sample> chunk;
    std::string got;
    long before = 0;
    try {
      while (stream.Next(&chunk)) before += static_cast<long>(chunk.size());
    } catch (const InputError& e) {
      got = e.what();
    }
    EXPECT_EQ(got, expected) << "block " << block;
    EXPECT_LE(before, 2);  // only the good lines before it came out
  }
}

TEST(RecordingStream, MissingFileAndEmptyFile) {
  EXPECT_THROW(RecordingStream("/nonexistent/rec.txt"), Error);
  const std::string path = WriteTemp("accelcal_stream_empty.txt", "# nothing\n");
  RecordingStream stream(path);
  std::vector<Sample> chunk;
  EXPECT_FALSE(stream.Next(&chunk));
  EXPECT_THROW(RecordingStream(path, 0), Error);
}

}  // namespace
}  // namespace accelcal
