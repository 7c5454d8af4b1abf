// `angioray render --crop / --clip / --clip-facing / --slab`: what they cut away shows black, the
// sidecar keeps them and renders the same bytes again, bad values get one line naming the flag.
#include <algorithm>
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

class ClippingCli : public test_support::PhantomFolderTest {
 protected:
  const char* folderPrefix() const override { return "clipping-cli"; }
  // Renders at theta = 0 (image right = +i) with the medium level; returns the exit and output.
  test_support::ProgramRun render(const std::string& out, const std::string& extra) {
    return runAngioray("render " + file("phantom.nrrd") + " --quality medium --tf cta-vessels-bone -o " +
                       file(out) + " " + extra);
  }
  // The pixels of the columns [x0, x1) that are not black.
  static int litPixels(const test_support::Pixels& image, int x0, int x1) {
    int lit = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = x0; x < x1; ++x) lit += image.at(x, y)[0] + image.at(x, y)[1] + image.at(x, y)[2] > 0;
    return lit;
  }
};

TEST_F(ClippingCli, CropToTheLeftHalfLeavesTheRightHalfBlack) {
  // The phantom's domain is about 405 mm wide along i: the crop keeps i <= 150 mm.
  ASSERT_EQ(render("crop.png", "--crop 0,150,0,1000,0,2000").exitCode, 0);
  ASSERT_EQ(render("plain.png", "").exitCode, 0);
  const test_support::Pixels cropped = pixelsOf(file("crop.png")), plain = pixelsOf(file("plain.png"));
  const int half = cropped.width / 2;
  EXPECT_EQ(litPixels(cropped, half, cropped.width), 0);
  EXPECT_GT(litPixels(plain, half, plain.width), 1000);
  EXPECT_GT(litPixels(cropped, 0, half - 20), 1000);
}

TEST_F(ClippingCli, EveryFlagCutsSomethingAndItsSidecarRendersTheSameBytes) {
  ASSERT_EQ(render("plain.png", "").exitCode, 0);
  const std::string plain = test_support::fileBytes(file("plain.png"));
  const std::pair<std::string, std::string> flags[] = {
      {"crop", "--crop 50,350,60,300,200,900"},
      {"clip", "--clip 200,200,600,0.5,-1,0.2"},
      {"facing", "--clip-facing 10"},
      {"slab", "--slab -20,60 --mip"},
      {"all", "--crop 50,350,60,300,200,900 --clip-facing -40 --slab 0,100"},
  };
  for (const auto& [name, flag] : flags) {
    const auto run = render(name + ".png", flag);
    ASSERT_EQ(run.exitCode, 0) << flag << ": " << run.output;
    const std::string image = test_support::fileBytes(file(name + ".png"));
    EXPECT_NE(image, plain) << flag;
    EXPECT_FALSE(readJson(name + ".png.json")["clipping"].is_null()) << flag;
    const auto again =
        runAngioray("render --params " + file(name + ".png.json") + " -o " + file(name + "-again.png"));
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(test_support::fileBytes(file(name + "-again.png")), image) << flag;
  }
  EXPECT_EQ(readJson("slab.png.json")["clipping"]["slab"]["thickness_mm"], 60.0);
  EXPECT_EQ(readJson("facing.png.json")["clipping"]["plane"]["facing_viewer"], true);
}

TEST_F(ClippingCli, BadValuesGetOneLineNamingTheFlag) {
  const std::pair<std::string, std::string> cases[] = {
      {"--crop 1,2,3", "--crop"},
      {"--crop 0,1,0,1,0,nan", "--crop"},
      {"--crop 0,1,5,4,0,1", "--crop"},
      {"--crop 0,1,0,1,0,1,", "--crop"},
      {"--clip 1,2,3,0,0,0", "--clip"},
      {"--clip 1,2,3,0,0,x", "--clip"},
      {"--clip-facing inf", "--clip-facing"},
      {"--slab 0,0", "--slab"},
      {"--slab 0,-5", "--slab"},
      {"--slab 1e999,5", "--slab"},
      {"--image-window 0,10,0", "--image-window"},
      {"--image-window 10,0,0,10", "--image-window"},
      {"--image-window 0,10,0,nan", "--image-window"},
  };
  for (const auto& [flag, name] : cases) {
    const auto run = render("bad.png", flag);
    EXPECT_NE(run.exitCode, 0) << flag;
    EXPECT_EQ(lineCount(run.output), 1) << flag << ": " << run.output;
    EXPECT_NE(run.output.find(name), std::string::npos) << flag << ": " << run.output;
  }
  EXPECT_FALSE(std::filesystem::exists(file("bad.png")));
}

// --image-window renders the whole image's pixels in that part of the image plane (what a zoomed
// view shows and exports): from 20 mm right of the image centre on, pixel for pixel; its sidecar
// keeps the window and renders the same bytes again. At 23 degrees: at 0 degrees, and in the
// column through the volume centre, nearest-neighbour samples fall exactly halfway between voxels
// of this even-sized phantom, where rays that differ by float rounding may pick either voxel.
TEST_F(ClippingCli, AnImageWindowIsThatPartOfTheWholeImage) {
  ASSERT_EQ(render("whole.png", "--angle 23").exitCode, 0);
  const auto run = render("right.png", "--angle 23 --image-window 20,1e4,-1e4,1e4");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const test_support::Pixels whole = pixelsOf(file("whole.png")), right = pixelsOf(file("right.png"));
  // The window reaches the image's right edge; which pixels a window covers is core's (tested there).
  const int x0 = whole.width - right.width;
  ASSERT_GT(x0, whole.width / 2);
  ASSERT_EQ(right.height, whole.height);
  int differing = 0;
  for (int y = 0; y < right.height; ++y)
    for (int x = 0; x < right.width; ++x)
      differing += !std::equal(right.at(x, y), right.at(x, y) + right.channels, whole.at(x0 + x, y));
  EXPECT_EQ(differing, 0);
  EXPECT_GT(litPixels(right, 0, right.width), 1000);
  EXPECT_DOUBLE_EQ(readJson("right.png.json")["view"]["window"]["left_mm"].get<double>(), 20);
  const auto again =
      runAngioray("render --params " + file("right.png.json") + " -o " + file("again.png"));
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_EQ(test_support::fileBytes(file("again.png")), test_support::fileBytes(file("right.png")));
}

}  // namespace
}  // namespace angio
