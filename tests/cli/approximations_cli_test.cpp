// `angioray render --preintegrated`, `--adaptive` and `--adaptive-sampling`: images different from the exact one
// (approximations, on request only), recorded in the sidecar so that `render --params` gives the
// same bytes again; a sidecar from before the options renders the exact image; bad combinations
// are refused in one line.
#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/phantom_folder_test.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

using test_support::runAngioray;

class ApproximationsCli : public test_support::PhantomFolderTest {
 protected:
  const char* folderPrefix() const override { return "approximations-cli"; }
  test_support::ProgramRun render(const std::string& out, const std::string& extra) {
    return runAngioray(
        "render " + file("phantom.nrrd") +
        " --quality medium --filter trilinear --osd 3 --tf cta-vessels-bone --angle 30 -o " + file(out) +
        " " + extra);
  }
  std::string bytes(const std::string& name) const { return test_support::fileBytes(file(name)); }
};

TEST_F(ApproximationsCli, TheSidecarRecordsThemAndRendersTheSameBytesAgain) {
  ASSERT_EQ(render("exact.png", "").exitCode, 0);
  const auto run = render("pre.png", "--preintegrated");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto adaptive = render("adaptive.png", "--adaptive 0.02 --initial-step 2");
  ASSERT_EQ(adaptive.exitCode, 0) << adaptive.output;
  EXPECT_NE(bytes("pre.png"), bytes("exact.png"));
  EXPECT_NE(bytes("adaptive.png"), bytes("exact.png"));
  EXPECT_EQ(readJson("pre.png.json")["sampling"]["preintegrated"], true);
  EXPECT_EQ(readJson("exact.png.json")["sampling"]["preintegrated"], false);
  EXPECT_TRUE(readJson("exact.png.json")["sampling"]["adaptive"].is_null());
  EXPECT_EQ(readJson("adaptive.png.json")["sampling"]["adaptive"]["tolerance"], 0.02);
  EXPECT_EQ(readJson("adaptive.png.json")["sampling"]["adaptive"]["initial_step"], 2.0);
  const auto sampled =
      render("sampled.png", "--adaptive-sampling 2 --ray-levels 4 --oracle-tolerance 0.05");
  ASSERT_EQ(sampled.exitCode, 0) << sampled.output;
  EXPECT_NE(bytes("sampled.png"), bytes("pre.png"));
  EXPECT_TRUE(readJson("exact.png.json")["sampling"]["adaptive_sampling"].is_null());
  const nlohmann::json recorded = readJson("sampled.png.json")["sampling"]["adaptive_sampling"];
  EXPECT_EQ(recorded["levels"], 2);
  EXPECT_EQ(recorded["ray_levels"], 4);
  EXPECT_EQ(recorded["tolerance"], 0.05);
  for (const std::string name : {"pre", "exact", "adaptive", "sampled"}) {
    const auto again =
        runAngioray("render --params " + file(name + ".png.json") + " -o " + file(name + "-again.png"));
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(bytes(name + "-again.png"), bytes(name + ".png")) << name;
  }
}

TEST_F(ApproximationsCli, ASidecarWithoutTheKeyRendersPostClassified) {
  ASSERT_EQ(render("exact.png", "").exitCode, 0);
  nlohmann::json sidecar = readJson("exact.png.json");
  sidecar["sampling"].erase("preintegrated");
  sidecar["sampling"].erase("adaptive");
  sidecar["sampling"].erase("adaptive_sampling");
  std::ofstream(file("old.json")) << sidecar.dump();
  const auto run = runAngioray("render --params " + file("old.json") + " -o " + file("old.png"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(bytes("old.png"), bytes("exact.png"));
}

TEST_F(ApproximationsCli, BadCombinationsAndValuesGetOneLine) {
  for (const std::string flags :
       {"--adaptive 0.01 --mip", "--initial-step 2", "--adaptive 0", "--adaptive nan",
        "--adaptive 0.01 --initial-step 1000", "--adaptive-sampling 3 --adaptive 0.01",
        "--adaptive-sampling 3 --mip", "--oracle-tolerance 0.1", "--ray-levels 4",
        "--adaptive-sampling 9", "--adaptive-sampling 4 --ray-levels 2",
        "--adaptive-sampling 3 --oracle-tolerance nan"}) {
    const auto run = render("bad.png", flags);
    EXPECT_NE(run.exitCode, 0) << flags;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << flags << ": " << run.output;
    EXPECT_FALSE(std::filesystem::exists(file("bad.png"))) << flags;
  }
}

}  // namespace
}  // namespace angio
