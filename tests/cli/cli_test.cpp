// The `angioray` executable end to end: exit codes, one-line errors, files written.
#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/run_angioray.h"
#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;

using angio::test_support::runAngioray;
using CliRun = angio::test_support::ProgramRun;

int lineCount(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir =
        fs::temp_directory_path() /
        ("angioray-cli-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
};

TEST_F(Cli, HelpWorksEverywhere) {
  for (std::string command : {"", "info ", "render ", "phantom ", "demo "}) {
    const CliRun run = runAngioray(command + "--help");
    EXPECT_EQ(run.exitCode, 0) << command;
    EXPECT_NE(run.output.find("--help"), std::string::npos) << command;
  }
}

TEST_F(Cli, MissingVolumeIsOneLineNamingTheFile) {
  const CliRun run =
      runAngioray("render " + (dir / "nothing.mha").string() + " --out " + (dir / "x.png").string());
  EXPECT_NE(run.exitCode, 0);
  EXPECT_EQ(lineCount(run.output), 1) << run.output;
  EXPECT_NE(run.output.find("nothing.mha"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST_F(Cli, BadOptionValuesAreRejected) {
  EXPECT_NE(runAngioray("phantom " + (dir / "p.mha").string() + " --size 12x12").exitCode, 0);
  EXPECT_NE(runAngioray("render a.mha --out b.png --isd -1").exitCode, 0);
  EXPECT_NE(runAngioray("render a.mha --out b.png --filter cubic").exitCode, 0);
  EXPECT_NE(runAngioray("render a.mha --out b.png --axis x").exitCode, 0);
}

TEST_F(Cli, PhantomThenInfoThenRenderEveryQuality) {
  const fs::path volume = dir / "phantom.mha", centerlines = dir / "phantom.csv";
  const CliRun phantom =
      runAngioray("phantom " + volume.string() + " --size 64x64x150 --style simple --centerlines " +
                  centerlines.string());
  ASSERT_EQ(phantom.exitCode, 0) << phantom.output;
  EXPECT_TRUE(fs::exists(volume));
  EXPECT_GT(fs::file_size(centerlines), 100u);

  const CliRun info = runAngioray("info " + volume.string());
  ASSERT_EQ(info.exitCode, 0) << info.output;
  EXPECT_NE(info.output.find("64 x 64 x 150"), std::string::npos) << info.output;

  for (std::string quality : {"fast", "medium", "high"}) {
    const fs::path out = dir / (quality + ".png");
    const CliRun render = runAngioray("render " + volume.string() + " --quality " + quality +
                                      " --angle 30 --out " + out.string());
    ASSERT_EQ(render.exitCode, 0) << render.output;
    EXPECT_GT(fs::file_size(out), 100u);
  }
  const CliRun mip = runAngioray("render " + volume.string() + " --mip --quality fast --out " +
                                 (dir / "mip.exr").string());
  EXPECT_EQ(mip.exitCode, 0) << mip.output;
  EXPECT_TRUE(fs::exists(dir / "mip.exr"));
}

TEST_F(Cli, UnknownTransferFunctionNamesIt) {
  const fs::path volume = dir / "v.nrrd";
  ASSERT_EQ(runAngioray("phantom " + volume.string() + " --size 32x32x64 --style simple").exitCode, 0);
  const CliRun run =
      runAngioray("render " + volume.string() + " --tf no-such-tf --out " + (dir / "x.png").string());
  EXPECT_NE(run.exitCode, 0);
  EXPECT_EQ(lineCount(run.output), 1) << run.output;
  EXPECT_NE(run.output.find("no-such-tf"), std::string::npos) << run.output;
}

}  // namespace
