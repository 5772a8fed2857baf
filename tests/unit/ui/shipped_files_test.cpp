// Where the program finds its shipped procedures and scenarios (ui/cli/shipped_files.h): beside
// an installed program's bin/ (any prefix), the source tree's for a program in the build tree,
// and a procedure or scenario named by its shipped name.
#include <algorithm>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "cli/shipped_files.h"

namespace accelcal::cli::shipped_files_test {
namespace {
namespace fs = std::filesystem;

class ShippedFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("accelcal_shipped_" + std::to_string(::getpid()));
    fs::create_directories(root_ / "bin");
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
};

TEST_F(ShippedFiles, AnInstalledProgramFindsShareBesideItsBin) {
  EXPECT_TRUE(ShippedDirFrom(root_ / "bin", kShippedProcedures).empty());  // nothing installed
  fs::create_directories(root_ / "share/accelcal/procedures");
  EXPECT_EQ(ShippedDirFrom(root_ / "bin", kShippedProcedures), root_ / "share/accelcal/procedures");
  EXPECT_TRUE(ShippedDirFrom(root_ / "bin", kShippedScenarios).empty());
}

TEST_F(ShippedFiles, AProgramInTheBuildTreeFindsTheSourceTrees) {
  const fs::path build = fs::path(ACCELCAL_BINARY).parent_path();
  EXPECT_EQ(ShippedDirFrom(build, kShippedScenarios), fs::path(ACCELCAL_SOURCE_DIR) / "scenarios");
  EXPECT_EQ(ShippedDirFrom(build / "tests", kShippedProcedures), fs::path(ACCELCAL_SOURCE_DIR) / "procedures");
}

TEST_F(ShippedFiles, AShippedOneIsNamedByItsFileName) {
  // This test program runs in the build tree: the source tree's files are the shipped ones.
  const std::string noise = (fs::path(ACCELCAL_SOURCE_DIR) / "procedures/noise.toml").string();
  EXPECT_EQ(ResolveShipped(kShippedProcedures, "noise.toml"), noise);
  EXPECT_EQ(ResolveShipped(kShippedProcedures, "noise"), noise);
  EXPECT_EQ(ResolveShipped(kShippedScenarios, "clumsy_bump"),
            (fs::path(ACCELCAL_SOURCE_DIR) / "scenarios/clumsy_bump.toml").string());
  // A path, or a name shipped nowhere, is left to the reader.
  EXPECT_EQ(ResolveShipped(kShippedProcedures, "./noise.toml"), "./noise.toml");
  EXPECT_EQ(ResolveShipped(kShippedProcedures, "no_such_procedure"), "no_such_procedure");
  EXPECT_EQ(ResolveShipped(kShippedScenarios, "noise.toml"), "noise.toml");
  const std::vector<std::string> scenarios = ShippedNames(kShippedScenarios);
  EXPECT_NE(std::find(scenarios.begin(), scenarios.end(), "bench_default.toml"), scenarios.end());
  EXPECT_TRUE(std::is_sorted(scenarios.begin(), scenarios.end()));
}

TEST_F(ShippedFiles, TheFullCalibrationIsFoundByItsFormerName) {
  // procedures/seed_calibration.toml became full_calibration.toml: the old name, with or without
  // ".toml", and the old path in the source tree (a script's, a session's notes) find the new file.
  const std::string full = (fs::path(ACCELCAL_SOURCE_DIR) / "procedures/full_calibration.toml").string();
  EXPECT_EQ(ResolveShipped(kShippedProcedures, "seed_calibration.toml"), full);
  EXPECT_EQ(ResolveShipped(kShippedProcedures, "seed_calibration"), full);
  EXPECT_EQ(ResolveShipped(kShippedProcedures, "procedures/seed_calibration.toml"), full);
  EXPECT_EQ(ResolveShipped(kShippedProcedures,
                           (fs::path(ACCELCAL_SOURCE_DIR) / "procedures/seed_calibration.toml").string()),
            full);
  // Not a scenario's old name; and a file of that name that exists is itself.
  EXPECT_EQ(ResolveShipped(kShippedScenarios, "seed_calibration.toml"), "seed_calibration.toml");
  const fs::path own = root_ / "seed_calibration.toml";
  { std::ofstream(own) << "# a lab's own\n"; }
  EXPECT_EQ(ResolveShipped(kShippedProcedures, own.string()), own.string());
}

TEST_F(ShippedFiles, ATransformResolvesAnOptionsValue) {
  CLI::App app{"demo", "demo"};
  std::string procedure;
  app.add_option("--procedure", procedure)->transform(ShippedFile(kShippedProcedures));
  app.parse("--procedure drift", false);
  EXPECT_EQ(procedure, (fs::path(ACCELCAL_SOURCE_DIR) / "procedures/drift.toml").string());
}

}  // namespace
}  // namespace accelcal::cli::shipped_files_test
