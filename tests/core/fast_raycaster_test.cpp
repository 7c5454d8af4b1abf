// The fast raycaster against the reference (an independent path through the same rendering
// model): with ERT off the images must agree within 1/255 per channel everywhere. They agree up
// to float rounding, since every evaluated sample uses the same operations and only provably
// transparent samples are skipped; the test checks the documented tolerance and counts.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/fast_raycaster.h"
#include "phantom/phantom.h"
#include "core/reference_raycaster.h"
#include "io/tf_file.h"
#include "io/volume_reader.h"
#include "tests/support/image_difference.h"

namespace angio {
namespace {

using test_support::maxChannelDifference;

struct Case {
  Axis axis;
  Quality quality;
  bool shading;
  bool mip;
  double angle;
};

std::string describe(const Case& c) {
  return std::string("axis ") + toString(c.axis) + " " + toString(c.quality) +
         (c.mip       ? " mip"
          : c.shading ? " shaded"
                      : " unshaded") +
         " angle " + std::to_string(c.angle);
}

// Renders each case with both raycasters, ERT off, and compares.
void expectSameImages(const Volume& volume, const TransferFunction& tf, const std::vector<Case>& cases) {
  const TfTable table = buildTable(tf);
  for (Axis axis : {Axis::i, Axis::j, Axis::k}) {
    const SliceTiles tiles = buildSliceTiles(volume, axis);
    const TileClassification visible(tiles, singleTable(table), /*mip=*/true);  // DVR and MIP
    for (const Case& c : cases) {
      if (c.axis != axis) continue;
      RenderParams p;
      p.axis = c.axis;
      p.angleDeg = c.angle;
      p.sampling = qualitySampling(c.quality);
      p.sampling.ert = 1.0;
      p.shading.enabled = c.shading;
      p.compositing = c.mip ? Compositing::mip : Compositing::dvr;
      p.mip = {tf.mipWindow, tf.mipLevel};
      const Image reference = renderReference(volume, table, p);
      FastRenderStats stats;
      const Image fast = renderFast(volume, visible, table, p, {}, &stats);
      ASSERT_EQ(fast.width, reference.width) << describe(c);
      ASSERT_EQ(fast.height, reference.height) << describe(c);
      EXPECT_LE(maxChannelDifference(fast, reference), 1.f / 255.f) << describe(c);
      // It must have skipped something, or the comparison proves nothing about skipping.
      FastRenderOptions everything;
      everything.skipEmpty = false;
      FastRenderStats all;
      renderFast(volume, visible, table, p, everything, &all);
      EXPECT_LT(stats.samples, all.samples) << describe(c);
    }
  }
}

// 24 angles (every 15 degrees, offset so no angle is axis-aligned only), spread over every
// combination of axis, quality level, shading on/off and MIP so each combination sees several.
std::vector<Case> coverage(int anglesPerCombination) {
  std::vector<Case> cases;
  int n = 0;
  for (Axis axis : {Axis::i, Axis::j, Axis::k})
    for (Quality quality : {Quality::fast, Quality::medium, Quality::high})
      for (int mode = 0; mode < 3; ++mode)  // shaded, unshaded, MIP
        for (int a = 0; a < anglesPerCombination; ++a, ++n)
          cases.push_back({axis, quality, mode == 0, mode == 2, 7.5 + 15.0 * (n % 24)});
  return cases;
}

TEST(FastRaycaster, MatchesReferenceOnPhantom) {
  PhantomOptions options;
  options.style = PhantomStyle::simple;
  options.dims = {48, 48, 112};
  const Phantom phantom = generatePhantom(options);
  expectSameImages(phantom.volume, loadPresetOrFile("cta-vessels-bone"), coverage(2));
}

TEST(FastRaycaster, MatchesReferenceOnRealAorta) {
  const std::filesystem::path aorta = std::filesystem::path(ANGIORAY_SHARED_DATA) / "aorta.mha";
  ASSERT_TRUE(std::filesystem::exists(aorta))
      << aorta << " (../shared/data is beside every checkout and CI)";
  const Volume volume = readVolume(aorta).volume;
  // Fitted to this dataset's uncalibrated values (lumen ~1200-2400).
  const TransferFunction tf =
      loadTransferFunction(std::string(ANGIORAY_TEST_DATA) + "/aorta-vmtk-tf.json");
  std::vector<Case> cases;
  for (int n = 0; n < 24; ++n) {
    const Axis axis = n % 3 == 0 ? Axis::k : n % 3 == 1 ? Axis::j : Axis::i;
    const Quality quality = n % 8 == 0 ? Quality::high : n % 2 ? Quality::fast : Quality::medium;
    cases.push_back({axis, quality, n % 4 != 1, n % 6 == 5, 15.0 * n + 3});
  }
  expectSameImages(volume, tf, cases);
}

// MIP through a window: a ray's maximum starts at the window's black, so what lies below it is
// skipped, and a ray ends once the window shows it white. Neither may change a pixel, with a crop
// box and a plane clipping some rays away entirely (transparent, not black). A window showing every
// density evaluates more.
TEST(FastRaycaster, MipSkipsBelowTheWindowAndStopsAtWhite) {
  const Volume volume =
      generatePhantom({.dims = {48, 48, 112}, .seed = 2, .style = PhantomStyle::realistic}).volume;
  const TfTable table = buildTable(loadPresetOrFile("cta-vessels-bone"));
  for (Axis axis : {Axis::k, Axis::i}) {
    const SliceTiles tiles = buildSliceTiles(volume, axis);
    const TileClassification visible(tiles, singleTable(table), /*mip=*/true);
    for (Quality quality : {Quality::fast, Quality::medium, Quality::high})
      for (bool clipped : {false, true}) {
        RenderParams p;
        p.axis = axis;
        p.angleDeg = 97;  // rays across the table, not through it: columns of air above the body
        p.sampling = qualitySampling(quality);
        p.compositing = Compositing::mip;
        if (clipped) {
          const glm::dvec3 extent = domainExtent(volume);
          p.clipping.crop = CropBox{0.2 * extent, 0.9 * extent};
          p.clipping.plane = ClipPlane{false, 0, 0.5 * extent, {0.3, -0.8, 0.5}};
        }
        const auto where = [&] {
          return std::string(toString(axis)) + " " + toString(quality) + (clipped ? " clipped" : "");
        };
        p.mip = {.window = 5000, .level = 1000};  // no density black or white
        FastRenderStats wideStats;
        const Image wide = renderFast(volume, visible, table, p, {}, &wideStats);
        EXPECT_LE(maxChannelDifference(wide, renderReference(volume, table, p)), 1.f / 255.f) << where();
        // Black up to 175 HU and white from 325 HU; black up to 950 HU (only bone shows), so that
        // whole columns, clipped away or not, are never started.
        for (const MipWindow window :
             {MipWindow{.window = 150, .level = 250}, MipWindow{.window = 100, .level = 1000}}) {
          p.mip = window;
          FastRenderStats stats;
          const Image narrow = renderFast(volume, visible, table, p, {}, &stats);
          EXPECT_LE(maxChannelDifference(narrow, renderReference(volume, table, p)), 1.f / 255.f)
              << where() << " level " << window.level;
          EXPECT_LT(stats.samples, wideStats.samples / 2) << where() << " level " << window.level;
        }
      }
  }
}

// A classification belongs to its tiles' axis and its TFs: handed another's, the raycaster refuses
// rather than skipping tiles by the wrong visibility.
TEST(FastRaycaster, RefusesAClassificationOfAnotherAxisOrOtherTfs) {
  PhantomOptions options;
  options.style = PhantomStyle::simple;
  options.dims = {32, 32, 48};
  const Phantom phantom = generatePhantom(options);
  const TfTable table = buildTable(loadPresetOrFile("cta-vessels-bone"));
  const TfTable other = table;
  const SliceTiles tilesK = buildSliceTiles(phantom.volume, Axis::k);
  const TileClassification classification(tilesK, table);
  RenderParams params;
  params.sampling = qualitySampling(Quality::fast);
  EXPECT_NO_THROW(renderFast(phantom.volume, classification, table, params));
  EXPECT_THROW(renderFast(phantom.volume, classification, other, params), std::logic_error);
  params.axis = Axis::j;
  EXPECT_THROW(renderFast(phantom.volume, classification, table, params), std::logic_error);
  EXPECT_TRUE(classification.classifies(singleTable(table)));
  EXPECT_FALSE(classification.classifies(singleTable(other)));
}

}  // namespace
}  // namespace angio
