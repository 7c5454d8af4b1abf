// Labels on the command line: `phantom --labels` writes the ground truth, `segment` writes labels
// from the density, `render --labels --hide` cuts them out and its sidecar renders the same bytes
// again; bad label input gets one line naming the file.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/phantom_folder_test.h"
#include "tests/support/png_pixels.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

using test_support::pixelsOf;
using test_support::runAngioray;

int lineCount(const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); }

class LabelsCli : public test_support::PhantomFolderTest {
 protected:
  const char* folderPrefix() const override { return "labels-cli"; }
  bool withLabels() const override { return true; }
  std::string render(const std::string& out, const std::string& extra) {
    const auto run =
        runAngioray("render " + file("phantom.nrrd") + " --quality medium --tf cta-vessels-bone -o " +
                    file(out) + " " + extra);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return test_support::fileBytes(file(out));
  }
};

TEST_F(LabelsCli, HidingBoneChangesTheImageAndTheSidecarRendersItAgainByteForByte) {
  const std::string shown = render("shown.png", "--labels " + file("truth.nrrd"));
  const std::string hidden = render("hidden.png", "--labels " + file("truth.nrrd") + " --hide bone");
  const std::string ghost =
      render("ghost.png", "--labels " + file("truth.nrrd") + " --hide bone --show-removed");
  EXPECT_NE(shown, hidden);
  EXPECT_NE(hidden, ghost);
  render("plain.png", "");
  // Labels that render as unlabelled voxels change no pixel.
  // The decoded pixels (the file's metadata names the label file, the pixels do not).
  EXPECT_EQ(pixelsOf(file("shown.png")).values, pixelsOf(file("plain.png")).values);
  const nlohmann::json sidecar = readJson("hidden.png.json");
  EXPECT_EQ(sidecar["tf"]["labels"][0]["mode"], "hidden");
  const auto again =
      runAngioray("render --params " + file("hidden.png.json") + " -o " + file("again.png"));
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_EQ(test_support::fileBytes(file("again.png")), hidden);
}

TEST_F(LabelsCli, SegmentWritesLabelsThatRenderLikeTheGroundTruthsAndSlicerSegmentations) {
  const auto run = runAngioray("segment " + file("phantom.nrrd") + " --out " + file("auto.seg.nrrd"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  // The header of a Slicer segmentation names the segments.
  const std::string header = test_support::fileBytes(file("auto.seg.nrrd")).substr(0, 4000);
  EXPECT_NE(header.find("Segment0_Name:=bone"), std::string::npos) << header.substr(0, 600);
  const std::string hidden = render("auto.png", "--labels " + file("auto.seg.nrrd") + " --hide bone");
  EXPECT_NE(hidden, render("none.png", ""));
}

TEST_F(LabelsCli, BadLabelInputIsOneLineNamingTheFile) {
  const auto otherGrid =
      runAngioray("phantom " + file("small.nrrd") + " --size 48x48x100 --style simple --labels " +
                  file("small-labels.nrrd"));
  ASSERT_EQ(otherGrid.exitCode, 0) << otherGrid.output;
  for (const auto& [labels, problem] :
       {std::pair{file("small-labels.nrrd"), std::string("not on the volume's grid")},
        {file("missing.nrrd"), std::string("does not exist")}}) {
    const auto run =
        runAngioray("render " + file("phantom.nrrd") + " --labels " + labels + " -o " + file("x.png"));
    EXPECT_NE(run.exitCode, 0);
    EXPECT_EQ(lineCount(run.output), 1) << run.output;
    EXPECT_NE(run.output.find(labels), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(problem), std::string::npos) << run.output;
  }
  const auto unknown = runAngioray("render " + file("phantom.nrrd") + " --labels " + file("truth.nrrd") +
                                   " --hide kidney -o " + file("x.png"));
  EXPECT_NE(unknown.exitCode, 0);
  EXPECT_NE(unknown.output.find("kidney"), std::string::npos) << unknown.output;
  const auto noLabels =
      runAngioray("render " + file("phantom.nrrd") + " --hide bone -o " + file("x.png"));
  EXPECT_NE(noLabels.exitCode, 0);
  EXPECT_NE(noLabels.output.find("--labels"), std::string::npos) << noLabels.output;
  EXPECT_FALSE(std::filesystem::exists(file("x.png")));
}

}  // namespace
}  // namespace angio
