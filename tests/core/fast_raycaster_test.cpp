// The fast raycaster against the reference (an independent path through the same rendering
// model): with ERT off the images must agree within 1/255 per channel everywhere. They agree up
// to float rounding, since every evaluated sample uses the same operations and only provably
// transparent samples are skipped; the test checks the documented tolerance and counts.
#include <cmath>
#include <filesystem>

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
