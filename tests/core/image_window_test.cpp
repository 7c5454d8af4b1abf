// Image windows (RenderParams::window): the pixels a window covers worked out by hand, and a
// window's image against the same pixels of the whole image, from both raycasters, with every
// filter, DVR and MIP, regions and clipping.
#include <gtest/gtest.h>

#include "core/fast_raycaster.h"
#include "core/ray_pick.h"
#include "core/reference_raycaster.h"
#include "core/view_geometry.h"
#include "io/tf_file.h"
#include "phantom/phantom.h"
#include "tests/support/varying_regions.h"

namespace angio {
namespace {

// The pixels of `whole` that `view` (a window of it) covers.
Image cropOf(const Image& whole, const ViewGeometry& view) {
  Image crop = makeImage(view.width, view.height);
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x) crop.at(x, y) = whole.at(view.windowX + x, view.windowY + y);
  return crop;
}

TEST(ImageWindow, CoversThePixelsThatOverlapItCutToTheImage) {
  // W = 10, H = 6, D = 2 mm: pixel x covers h in [2x - 10, 2x - 8), row y covers v in (4 - 2y, 6 - 2y].
  EXPECT_EQ(windowPixels({-3, 3, -1, 1}, 10, 6, 2), (PixelSpan{3, 7, 2, 4}));
  EXPECT_EQ(windowPixels({-4, 4, -2, 2}, 10, 6, 2), (PixelSpan{3, 7, 2, 4}));  // edges on pixel edges
  EXPECT_EQ(windowPixels({-50, 50, -50, 50}, 10, 6, 2), (PixelSpan{0, 10, 0, 6}));
  EXPECT_EQ(windowPixels({7, 30, 4.5, 30}, 10, 6, 2), (PixelSpan{8, 10, 0, 1}));
  // Beside the image: one pixel at its nearest corner, never an empty image.
  EXPECT_EQ(windowPixels({40, 50, 40, 50}, 10, 6, 2), (PixelSpan{9, 10, 0, 1}));
}

TEST(ImageWindow, RaysAreTheWholeImagesRays) {
  const Volume volume = makeVolume({21, 31, 11}, {1, 0.8, 2}, encodeVoxel(0));
  RenderParams p;
  p.angleDeg = 37;
  const ViewGeometry whole = makeViewGeometry(volume, p);
  p.window = ImageWindow{-7.3, 4.1, -2.2, 9.6};
  const ViewGeometry window = makeViewGeometry(volume, p);
  EXPECT_EQ(window.wholeWidth, whole.width);
  EXPECT_EQ(window.wholeHeight, whole.height);
  for (int y = 0; y < window.height; ++y)
    for (int x = 0; x < window.width; ++x) {
      const glm::dvec3 a = window.rayOrigin(x, y),
                       b = whole.rayOrigin(window.windowX + x, window.windowY + y);
      EXPECT_NEAR(glm::length(a - b), 0, 1e-9);
    }
  const glm::dvec3 point(9.5, 3.2, 7.7);
  EXPECT_NEAR(imagePointOf(window, point).x + window.windowX, imagePointOf(whole, point).x, 1e-9);
  EXPECT_NEAR(imagePointOf(window, point).y + window.windowY, imagePointOf(whole, point).y, 1e-9);
}

struct Case {
  const char* name;
  RenderParams params;
};

std::vector<Case> cases(glm::dvec3 E) {
  std::vector<Case> all;
  for (Filter filter : {Filter::nearest, Filter::trilinear, Filter::mean})
    for (Compositing mode : {Compositing::dvr, Compositing::mip}) {
      RenderParams p;
      p.angleDeg = 23 + 61 * int(all.size());
      p.axis = all.size() % 3 == 2 ? Axis::i : Axis::k;
      p.sampling = qualitySampling(filter == Filter::trilinear ? Quality::high : Quality::medium);
      p.sampling.filter = filter;
      p.sampling.ert = 1.0;
      p.compositing = mode;
      all.push_back({toString(filter), p});
    }
  RenderParams cropped = all[1].params;
  cropped.clipping.crop = CropBox{E * 0.2, E * 0.7};
  all.push_back({"crop", cropped});
  return all;
}

TEST(ImageWindow, BothRaycastersRenderExactlyTheWholeImagesPixels) {
  const Volume volume =
      generatePhantom({.dims = {48, 48, 112}, .seed = 1, .style = PhantomStyle::simple}).volume;
  const TfTable table = buildTable(loadPresetOrFile("cta-vessels-bone"));
  const glm::dvec3 E = domainExtent(volume);
  for (const Case& c : cases(E)) {
    RenderParams p = c.params;
    const SliceTiles tiles = buildSliceTiles(volume, p.axis);
    const TileClassification classification(tiles, singleTable(table),
                                            p.compositing == Compositing::mip);
    const Image wholeFast = renderFast(volume, classification, table, p);
    const Image wholeReference = renderReference(volume, singleTable(table), p);
    // A window about the vessels, one reaching over the image's top left corner, one beside it.
    for (const ImageWindow window :
         {ImageWindow{-0.21 * E.x, 0.13 * E.x, -0.17 * E.z, 0.31 * E.z},
          ImageWindow{-2 * E.x, -0.1 * E.x, 0.2 * E.z, 2 * E.z}, ImageWindow{3 * E.x, 4 * E.x, 0, 1}}) {
      p.window = window;
      const ViewGeometry view = makeViewGeometry(volume, p);
      const Image fast = renderFast(volume, classification, table, p);
      ASSERT_EQ(fast.width, view.width) << c.name;
      ASSERT_EQ(fast.height, view.height) << c.name;
      EXPECT_TRUE(fast.pixels == cropOf(wholeFast, view).pixels) << c.name << " " << window.leftMm;
      const Image reference = renderReference(volume, singleTable(table), p);
      EXPECT_TRUE(reference.pixels == cropOf(wholeReference, view).pixels) << c.name;
    }
    // The first window shows vessels: the test compares something.
    p.window = ImageWindow{-0.21 * E.x, 0.13 * E.x, -0.17 * E.z, 0.31 * E.z};
    float brightest = 0;
    for (const glm::vec4& pixel : renderFast(volume, classification, table, p).pixels)
      brightest = std::max(brightest, pixel.r);
    EXPECT_GT(brightest, 0.3f) << c.name;
  }
}

TEST(ImageWindow, RegionsOfTheWindowGiveTheWholeImagesPixels) {
  const Volume volume =
      generatePhantom({.dims = {48, 48, 112}, .seed = 1, .style = PhantomStyle::simple}).volume;
  const auto [focus, context] = test_support::vesselRegionTables();
  RenderParams p;
  p.angleDeg = 140;
  p.sampling = qualitySampling(Quality::high);
  const ViewGeometry whole = makeViewGeometry(volume, p);
  const RayRegions wholeRegions = test_support::varyingRegions(whole, 5.f, 40, 7.3f, 60.f);
  const SliceTiles tiles = buildSliceTiles(volume, p.axis);
  const RegionTables wholeTables{&wholeRegions, &focus, &context, nullptr};
  const Image wholeImage = renderFast(volume, TileClassification(tiles, wholeTables), wholeTables, p);
  p.window = ImageWindow{-30, 25, -80, 140};
  const ViewGeometry view = makeViewGeometry(volume, p);
  const RayRegions regions = test_support::cropRegions(wholeRegions, whole.width, view);
  const RegionTables tables{&regions, &focus, &context, nullptr};
  const Image image = renderFast(volume, TileClassification(tiles, tables), tables, p);
  EXPECT_TRUE(image.pixels == cropOf(wholeImage, view).pixels);
}

TEST(ImageWindow, APickInTheWindowFindsTheWholeImagesPoint) {
  const Volume volume =
      generatePhantom({.dims = {48, 48, 112}, .seed = 1, .style = PhantomStyle::simple}).volume;
  const TfTable table = buildTable(loadPresetOrFile("cta-vessels-bone"));
  RenderParams p;
  p.angleDeg = 70;
  const ViewGeometry whole = makeViewGeometry(volume, p);
  const glm::dvec2 at(whole.width * 0.47 + 0.3, whole.height * 0.52 + 0.6);
  const auto expected = pickPoint(volume, singleTable(table), p, at, 0.5);
  ASSERT_TRUE(expected);
  p.window = ImageWindow{-40, 60, -100, 50};
  const ViewGeometry view = makeViewGeometry(volume, p);
  const auto picked =
      pickPoint(volume, singleTable(table), p, at - glm::dvec2(view.windowX, view.windowY), 0.5);
  ASSERT_TRUE(picked);
  EXPECT_NEAR(glm::length(picked->positionMm - expected->positionMm), 0, 1e-9);
}

}  // namespace
}  // namespace angio
