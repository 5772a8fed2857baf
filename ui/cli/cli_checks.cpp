#include "cli/cli_checks.h"

#include <charconv>
#include <cmath>
#include <filesystem>

#include <fmt/core.h>

#include "accelcal/base/error.h"

namespace accelcal::cli {
namespace {

// `text` as a finite number, or NaN.
double AsNumber(const std::string& text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    return std::nan("");
  return value;
}

}  // namespace

CLI::Validator NonNegative() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const double v = AsNumber(text);
        if (std::isnan(v)) return fmt::format("'{}' is not a number", text);
        return v < 0.0 ? fmt::format("must be 0 or more, not {}", text) : "";
      },
      "NUMBER >= 0", "NonNegative");
}

CLI::Validator Positive() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const double v = AsNumber(text);
        if (std::isnan(v)) return fmt::format("'{}' is not a number", text);
        return v <= 0.0 ? fmt::format("must be more than 0, not {}", text) : "";
      },
      "NUMBER > 0", "Positive");
}

CLI::Validator InputFile() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) throw Error(fmt::format("no such file: {}", path));
        if (std::filesystem::is_directory(path, ec))
          throw Error(fmt::format("{} is a directory, not a file", path));
        return "";
      },
      "FILE", "InputFile");
}

CLI::Validator InputFileOrBag() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) throw Error(fmt::format("no such file: {}", path));
        if (std::filesystem::is_directory(path, ec) &&
            !std::filesystem::exists(std::filesystem::path(path) / "metadata.yaml", ec))
          throw Error(fmt::format("{} is a directory, not a file (nor a ROS 2 bag folder: it "
                                  "holds no metadata.yaml)", path));
        return "";
      },
      "FILE|BAG", "InputFileOrBag");
}

}  // namespace accelcal::cli
