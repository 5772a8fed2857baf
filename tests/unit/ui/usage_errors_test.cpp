// A command line CLI11 refuses, told in our words (ui/cli/usage_errors.h): every CLI11 text a
// technician can meet, on a command line shaped like accelcal's.
#include <gtest/gtest.h>

#include "cli/cli_checks.h"
#include "cli/usage_errors.h"

namespace accelcal::cli::usage_errors_test {
namespace {

struct DemoLine {
  CLI::App app{"demo", "accelcal"};
  double speed = 1, latitude = 0, altitude = 0;
  std::optional<std::uint64_t> seed;
  std::string source = "sim", input, target, format = "text";
  std::vector<double> nominal;
  bool plain = false;
  int device_id = 0;
  DemoLine() {
    app.require_subcommand(0, 1);
    CLI::App* wizard = app.add_subcommand("wizard", "The wizard");
    wizard->add_option("--speed", speed, "sim: simulated seconds per wall-clock second")->check(NonNegative());
    wizard->add_option("--seed", seed, "sim: random seed");
    wizard->add_option("--source", source, "Sample source");
    wizard->add_flag("--plain", plain, "Plain line mode");
    CLI::Option* lat = wizard->add_option("--latitude", latitude, "Latitude");
    wizard->add_option("--altitude", altitude, "Altitude")->needs(lat);
    wizard->add_option("--gravity", speed, "Gravity")->excludes(lat);
    CLI::App* export_cal = app.add_subcommand("export-cal", "Export");
    export_cal->add_option("calibration", input, "Calibration file (JSON) or session file (.db)")->required();
    export_cal->add_option("--to", target, "Target format")->required()->check(CLI::IsMember({"c-header", "px4"}));
    export_cal->add_option("--nominal", nominal, "Nominal scale")->expected(1, 3);
    export_cal->add_option("--px4-device-id", device_id, "Device id");
    CLI::App* history = app.add_subcommand("history", "History");
    history->add_option("--format", format, "text or json")->check(CLI::IsMember({"text", "json"}));
    history->add_option("--range", speed, "A range")->check(CLI::Range(0.0, 10.0));
    RefuseNegativeWholeNumbers(app);
  }
  // The message for `args` (after the program's name), "" when they parse.
  std::string Message(std::vector<std::string> args) {
    args.insert(args.begin(), "accelcal");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    try {
      app.parse(static_cast<int>(argv.size()), argv.data());
    } catch (const CLI::ParseError& e) {
      return PlainUsageMessage(app, e, std::vector<std::string>(args.begin() + 1, args.end()));
    }
    return "";
  }
};

std::string MessageFor(std::vector<std::string> args) { return DemoLine().Message(std::move(args)); }

TEST(UsageErrors, AnOptionGivenTwiceNamesBothValues) {
  EXPECT_EQ(MessageFor({"wizard", "--speed", "20", "--speed", "1"}),
            "--speed is given twice (20 and 1): give it once");
  EXPECT_EQ(MessageFor({"wizard", "--speed=20", "--speed", "1", "--speed", "3"}),
            "--speed is given 3 times (20, 1 and 3): give it once");
  EXPECT_EQ(MessageFor({"export-cal", "c.json", "--to", "px4", "--nominal", "1", "2", "3", "4"}),
            "--nominal takes at most 3 values");
}

TEST(UsageErrors, AMissingValueSaysWhatItTakes) {
  EXPECT_EQ(MessageFor({"wizard", "--speed"}), "--speed needs a number after it");
  EXPECT_EQ(MessageFor({"wizard", "--seed"}), "--seed needs a whole number, 0 or more after it");
  EXPECT_EQ(MessageFor({"wizard", "--source"}), "--source needs a value after it");
}

TEST(UsageErrors, WhatIsRequiredIsNamedWithItsPurpose) {
  EXPECT_EQ(MessageFor({"export-cal", "--to", "px4"}),
            "accelcal export-cal needs its calibration: Calibration file (JSON) or session file (.db)");
  EXPECT_EQ(MessageFor({"export-cal", "c.json"}),
            "accelcal export-cal needs --to: Target format (one of c-header or px4)");
}

TEST(UsageErrors, AValueThatIsNotANumberOrNotAChoice) {
  EXPECT_EQ(MessageFor({"export-cal", "c.json", "--to", "px4", "--px4-device-id", "abc"}),
            "--px4-device-id: 'abc' is not a whole number");
  EXPECT_EQ(MessageFor({"history", "--format", "xml"}), "--format: 'xml' is not one of text or json");
  EXPECT_EQ(MessageFor({"history", "--range", "11"}), "--range: 11 is not between 0 and 10");
  EXPECT_EQ(MessageFor({"wizard", "--seed", "-3"}), "--seed: must be a whole number, 0 or more, not -3");
  // Our own validators' words are kept.
  EXPECT_EQ(MessageFor({"wizard", "--speed", "-1"}), "--speed: must be 0 or more, not -1");
  EXPECT_EQ(MessageFor({"wizard", "--plain=maybe"}), "--plain is a switch: it takes no value (or true/false)");
}

TEST(UsageErrors, UnexpectedWordsAndOptions) {
  EXPECT_EQ(MessageFor({"wizard", "foo"}), "accelcal wizard does not take 'foo'");
  EXPECT_EQ(MessageFor({"wizard", "--frobnicate"}), "accelcal wizard has no option '--frobnicate'");
  EXPECT_EQ(MessageFor({"--nope"}), "accelcal has no option '--nope'");
  EXPECT_EQ(MessageFor({"sesions"}), "'sesions' is not a command of accelcal");
  EXPECT_EQ(MessageFor({"wizard", "a", "b"}), "accelcal wizard does not take 'a' or 'b'");
}

TEST(UsageErrors, OptionsThatGoTogetherOrNot) {
  EXPECT_EQ(MessageFor({"wizard", "--altitude", "3"}), "--altitude needs --latitude too");
  EXPECT_EQ(MessageFor({"wizard", "--gravity", "9.8", "--latitude", "3"}),
            "--latitude and --gravity cannot be given together");
}

TEST(UsageErrors, AGoodCommandLineHasNoMessage) {
  EXPECT_EQ(MessageFor({"wizard", "--speed", "0", "--seed", "3"}), "");
}

}  // namespace
}  // namespace accelcal::cli::usage_errors_test
