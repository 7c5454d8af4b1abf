// `angioray render --preintegrated`: a different image from the exact one (an approximation, on
// request only), recorded in the sidecar so that `render --params` gives the same bytes again; a
// sidecar from before the option renders post-classified.
#include <string>

#include <gtest/gtest.h>

#include "tests/support/phantom_folder_test.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

using test_support::runAngioray;

class PreintegrationCli : public test_support::PhantomFolderTest {
 protected:
  const char* folderPrefix() const override { return "preintegration-cli"; }
  test_support::ProgramRun render(const std::string& out, const std::string& extra) {
    return runAngioray(
        "render " + file("phantom.nrrd") +
        " --quality medium --filter trilinear --osd 3 --tf cta-vessels-bone --angle 30 -o " + file(out) +
        " " + extra);
  }
  std::string bytes(const std::string& name) const { return test_support::fileContents(file(name)); }
};

TEST_F(PreintegrationCli, TheSidecarRecordsItAndRendersTheSameBytesAgain) {
  ASSERT_EQ(render("exact.png", "").exitCode, 0);
  const auto run = render("pre.png", "--preintegrated");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(bytes("pre.png"), bytes("exact.png"));
  EXPECT_EQ(readJson("pre.png.json")["sampling"]["preintegrated"], true);
  EXPECT_EQ(readJson("exact.png.json")["sampling"]["preintegrated"], false);
  for (const std::string name : {"pre", "exact"}) {
    const auto again =
        runAngioray("render --params " + file(name + ".png.json") + " -o " + file(name + "-again.png"));
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(bytes(name + "-again.png"), bytes(name + ".png")) << name;
  }
}

TEST_F(PreintegrationCli, ASidecarWithoutTheKeyRendersPostClassified) {
  ASSERT_EQ(render("exact.png", "").exitCode, 0);
  nlohmann::json sidecar = readJson("exact.png.json");
  sidecar["sampling"].erase("preintegrated");
  std::ofstream(file("old.json")) << sidecar.dump();
  const auto run = runAngioray("render --params " + file("old.json") + " -o " + file("old.png"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(bytes("old.png"), bytes("exact.png"));
}

}  // namespace
}  // namespace angio
