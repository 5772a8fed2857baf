#include "accelcal/bags/ros2_bag_folder.h"

#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "accelcal/bags/mcap_file.h"
#include "accelcal/bags/ros2_sqlite_file.h"
#include "accelcal/base/error.h"
#include "accelcal/base/text_scan.h"

namespace accelcal::bags {
namespace {

// A plain YAML scalar: blanks trimmed, one pair of quotes removed, `~` and `null` empty.
std::string YamlScalar(std::string_view text) {
  std::string_view v = detail::TrimBlanks(text);
  if (const size_t hash = v.find(" #"); hash != std::string_view::npos)
    v = detail::TrimBlanks(v.substr(0, hash));
  if (v.size() >= 2 && (v.front() == '"' || v.front() == '\'') && v.back() == v.front())
    v = v.substr(1, v.size() - 2);
  if (v == "~" || v == "null") return {};
  return std::string(v);
}

size_t Indent(std::string_view line) {
  size_t n = 0;
  while (n < line.size() && line[n] == ' ') ++n;
  return n;
}

}  // namespace

Ros2BagMetadata ParseRos2BagMetadata(const std::string& text, const std::string& source) {
  Ros2BagMetadata m;
  detail::LineReader lines(text);
  std::string_view line;
  bool in_paths = false;
  size_t paths_indent = 0;
  bool found_info = false;
  while (lines.Next(&line)) {
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::string_view trimmed = detail::TrimBlanks(line);
    if (trimmed.empty() || trimmed.front() == '#') continue;
    if (in_paths) {
      if (trimmed.front() == '-' && Indent(line) >= paths_indent) {
        m.relative_file_paths.push_back(YamlScalar(trimmed.substr(1)));
        continue;
      }
      in_paths = false;
    }
    if (Indent(line) == 0) {
      found_info |= trimmed.rfind("rosbag2_bagfile_information:", 0) == 0;
      continue;
    }
    // The keys wanted sit one level under rosbag2_bagfile_information.
    const size_t colon = trimmed.find(':');
    if (colon == std::string_view::npos) continue;
    const std::string_view key = trimmed.substr(0, colon);
    const std::string value = YamlScalar(trimmed.substr(colon + 1));
    if (key == "storage_identifier") m.storage_identifier = value;
    else if (key == "compression_format") m.compression_format = value;
    else if (key == "compression_mode") m.compression_mode = value;
    else if (key == "relative_file_paths") {
      // A flow list on the same line ("[a.db3, b.db3]"), or a block list below it.
      if (!value.empty() && value.front() == '[') {
        std::string_view rest(value);
        rest = rest.substr(1, rest.find(']') == std::string_view::npos ? rest.size() - 1 : rest.find(']') - 1);
        while (!rest.empty()) {
          const size_t comma = rest.find(',');
          const std::string item = YamlScalar(rest.substr(0, comma));
          if (!item.empty()) m.relative_file_paths.push_back(item);
          if (comma == std::string_view::npos) break;
          rest.remove_prefix(comma + 1);
        }
      } else {
        in_paths = true;
        paths_indent = Indent(line);
      }
    }
  }
  if (!found_info)
    throw Error(fmt::format("{}: not a rosbag2 metadata file (no rosbag2_bagfile_information)", source));
  if (m.relative_file_paths.empty())
    throw Error(fmt::format("{}: lists no files (relative_file_paths)", source));
  return m;
}

Ros2BagFolder::Ros2BagFolder(const std::string& folder) : folder_(folder) {
  const std::string yaml_path = folder + "/metadata.yaml";
  std::ifstream in(yaml_path, std::ios::binary);
  if (!in) throw Error(fmt::format("cannot read '{}'", yaml_path));
  std::ostringstream text;
  text << in.rdbuf();
  metadata_ = ParseRos2BagMetadata(text.str(), yaml_path);
  const std::string& mode = metadata_.compression_mode;
  if (!metadata_.compression_format.empty() && mode != "NONE" && !mode.empty())
    throw Error(fmt::format("{}: rosbag2 compressed its {} with {} (compression_mode {}): not "
                            "read; decompress it first (`ros2 bag convert`, or `{} -d` on each "
                            "file)", folder, mode == "FILE" ? "files whole" : "messages one by one",
                            metadata_.compression_format, mode, metadata_.compression_format));
  const std::string& storage = metadata_.storage_identifier;
  if (storage != "sqlite3" && storage != "mcap")
    throw Error(fmt::format("{}: its storage is '{}': sqlite3 and mcap are read", folder,
                            detail::PrintableExcerpt(storage, 40)));
  for (const std::string& relative : metadata_.relative_file_paths) {
    // rosbag2 before Foxy wrote the paths with the folder in front; either is found.
    std::string path = folder + "/" + relative;
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) {
      const size_t slash = relative.rfind('/');
      const std::string base = slash == std::string::npos ? relative : relative.substr(slash + 1);
      if (::stat((folder + "/" + base).c_str(), &info) == 0) path = folder + "/" + base;
      else throw Error(fmt::format("{}: its file '{}' (metadata.yaml) is not there", folder, relative));
    }
    if (storage == "mcap") files_.push_back(std::make_unique<McapFile>(path));
    else files_.push_back(std::make_unique<Ros2SqliteFile>(path));
  }
}

std::string Ros2BagFolder::Description() const {
  std::string out = files_.empty() ? "ROS 2 bag" : files_.front()->Description();
  if (files_.size() > 1) out += fmt::format(", {} files", files_.size());
  return out + ", from metadata.yaml";
}

std::optional<std::vector<TopicSummary>> Ros2BagFolder::IndexedTopics(bool with_counts) {
  std::vector<TopicSummary> out;
  for (const auto& file : files_) {
    const std::optional<std::vector<TopicSummary>> topics = file->IndexedTopics(with_counts);
    if (!topics) return std::nullopt;
    for (const TopicSummary& t : *topics) {
      auto it = std::find_if(out.begin(), out.end(), [&](const TopicSummary& o) { return o.name == t.name; });
      if (it == out.end()) {
        out.push_back(t);
        continue;
      }
      it->messages = it->messages < 0 || t.messages < 0 ? -1 : it->messages + t.messages;
      if (t.first_ns != 0 && (it->first_ns == 0 || t.first_ns < it->first_ns)) it->first_ns = t.first_ns;
      it->last_ns = std::max(it->last_ns, t.last_ns);
    }
  }
  return out;
}

bool Ros2BagFolder::ReadBatch(MessageSink* sink) {
  while (current_ < files_.size()) {
    if (files_[current_]->ReadBatch(sink)) return true;
    ++current_;
  }
  return false;
}

std::vector<std::string> Ros2BagFolder::Notes() const {
  std::vector<std::string> out;
  for (const auto& file : files_)
    for (const std::string& n : file->Notes())
      out.push_back(files_.size() > 1 ? fmt::format("{} ({})", n, "one of its files") : n);
  return out;
}

}  // namespace accelcal::bags
