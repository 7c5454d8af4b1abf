// The DVR+CPR hybrid's compositing (vessel/cpr_hybrid.h): footprint from ray regions, the CPR
// inside the cut, the DVR outside, the linear transition band in mm.
#include "vessel/cpr_hybrid.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/view_geometry.h"
#include "vessel/cpr.h"

namespace angio {
namespace {

Image filled(int width, int height, glm::vec4 color) {
  Image image = makeImage(width, height);
  for (auto& pixel : image.pixels) pixel = color;
  return image;
}

// Regions of a width x height view where the pixels in `focusPixels` have a focus interval, every
// pixel also a context interval behind it.
RayRegions regionsWithFocus(int width, int height, const std::vector<glm::ivec2>& focusPixels) {
  RayRegions regions;
  regions.width = width;
  regions.height = height;
  regions.rayBegin.push_back(0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (const glm::ivec2& p : focusPixels)
        if (p == glm::ivec2(x, y)) regions.intervals.push_back({1.f, 2.f, Region::focus});
      regions.intervals.push_back({5.f, 9.f, Region::context});
      regions.rayBegin.push_back(std::uint32_t(regions.intervals.size()));
    }
  }
  return regions;
}

TEST(CprHybrid, FootprintIsThePixelsWhoseRayMeetsTheFocus) {
  const RayRegions regions = regionsWithFocus(4, 3, {{1, 0}, {3, 2}});
  const std::vector<std::uint8_t> footprint = focusFootprint(regions);
  ASSERT_EQ(footprint.size(), 12u);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x)
      EXPECT_EQ(footprint[y * 4 + x], (x == 1 && y == 0) || (x == 3 && y == 2)) << x << "," << y;
}

TEST(CprHybrid, HardCutShowsTheCprInsideAndTheDvrOutside) {
  const Image dvr = filled(5, 5, {0.2f, 0.3f, 0.4f, 0.5f});
  Image cpr = filled(5, 5, {0.9f, 0.8f, 0.7f, 1.f});
  cpr.at(2, 3) = glm::vec4(0.f);  // not sampled
  const std::vector<std::uint8_t> footprint = focusFootprint(regionsWithFocus(5, 5, {{2, 2}, {2, 3}}));
  const Image out = compositeHybrid(dvr, cpr, footprint, {0.0, 1.0});
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x)
      EXPECT_EQ(out.at(x, y), x == 2 && y == 2 ? cpr.at(x, y) : dvr.at(x, y)) << x << "," << y;
}

TEST(CprHybrid, TransitionFadesTheCprLinearlyOverItsWidthInMm) {
  const int width = 21;
  const Image dvr = filled(width, 1, {0.f, 0.f, 1.f, 1.f});
  const Image cpr = filled(width, 1, {1.f, 0.f, 0.f, 1.f});
  const std::vector<std::uint8_t> footprint = focusFootprint(regionsWithFocus(width, 1, {{10, 0}}));
  const double pixelMm = 0.5, transitionMm = 2.0;  // the band is 4 pixels wide
  const Image out = compositeHybrid(dvr, cpr, footprint, {transitionMm, pixelMm});
  for (int x = 0; x < width; ++x) {
    const double distanceMm = std::abs(x - 10) * pixelMm;
    const float weight = float(std::max(0.0, 1.0 - distanceMm / transitionMm));
    EXPECT_NEAR(out.at(x, 0).r, weight, 1e-6) << x;
    EXPECT_NEAR(out.at(x, 0).b, 1.f - weight, 1e-6) << x;
    if (weight == 0.f) EXPECT_EQ(out.at(x, 0), dvr.at(x, 0)) << x;
  }
}

TEST(CprHybrid, MismatchedSizesAndBadSettingsAreRejected) {
  const Image dvr = filled(4, 4, glm::vec4(0.f)), small = filled(3, 4, glm::vec4(0.f));
  const std::vector<std::uint8_t> footprint(16, 0);
  EXPECT_THROW(compositeHybrid(dvr, small, footprint, {}), std::invalid_argument);
  EXPECT_THROW(compositeHybrid(dvr, dvr, std::vector<std::uint8_t>(15, 0), {}), std::invalid_argument);
  EXPECT_THROW(compositeHybrid(dvr, dvr, footprint, {-1.0, 1.0}), std::invalid_argument);
}

// A volume whose HU varies in every direction (so any misplaced sample shows) and a view of it.
Volume patternedVolume() {
  Volume volume = makeVolume({24, 20, 16}, {1.0, 1.25, 1.5});
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 24; ++i)
        volume.voxels[volume.indexOf(i, j, k)] =
            encodeVoxel(int(400 * std::sin(0.7 * i + 1.3 * j + 0.4 * k)));
  return volume;
}

// Every third pixel of every row in a diagonal band: the "focus footprint" need not be a tube's here.
std::vector<std::uint8_t> bandFootprint(int width, int height) {
  std::vector<std::uint8_t> footprint(std::size_t(width) * height, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      footprint[std::size_t(y) * width + x] = std::abs(x - y) < 6 && x % 3 != 1;
  return footprint;
}

TEST(CprHybrid, InPlaceCompositingEqualsTheFullImagePipeline) {
  const Volume volume = patternedVolume();
  const CenterlinePath path{"oblique", {{{3, 4, 2}, 1}, {{12, 10, 9}, 1}, {{20, 15, 20}, 1}}};
  TransferFunction tf;
  tf.points = {{-500, {0, 0, 1}, 0}, {500, {1, 0.5f, 0}, 1}};
  CprDisplay grey, colored;
  colored.tf = tf;
  for (const double angle : {0.0, 35.0, 130.0}) {
    const ViewGeometry view = cprView(volume, Axis::k, angle, 0.7);
    const CprLayout layout = layoutCpr({path}, view, {CprMode::projected});
    const std::vector<float> hu = resampleCpr(volume, layout);
    const std::vector<std::uint8_t> footprint = bandFootprint(view.width, view.height);
    const Image dvr = filled(view.width, view.height, {0.1f, 0.2f, 0.3f, 0.6f});
    for (const CprDisplay& base : {grey, colored}) {
      CprDisplay display = base;
      display.centerlineMarker = display.ruler = false;
      for (const double transitionMm : {0.0, 2.0}) {
        const HybridCompositing settings{transitionMm, view.pixelMm};
        const Image expected =
            compositeHybrid(dvr, displayCpr(layout, hu, display), footprint, settings);
        Image image = dvr;
        compositeCprInPlace(image, volume, layout, footprint, display, settings);
        std::size_t changed = 0;
        for (int y = 0; y < view.height; ++y)
          for (int x = 0; x < view.width; ++x) {
            ASSERT_EQ(image.at(x, y), expected.at(x, y))
                << angle << " deg, T " << transitionMm << ": " << x << "," << y;
            changed += image.at(x, y) != dvr.at(x, y);
          }
        EXPECT_GT(changed, 10u) << angle;  // the CPR did show
      }
    }
  }
  Image wrongSize = filled(3, 3, glm::vec4(0.f));
  const ViewGeometry view = cprView(volume, Axis::k, 0, 0.7);
  EXPECT_THROW(compositeCprInPlace(wrongSize, volume, layoutCpr({path}, view, {CprMode::projected}),
                                   std::vector<std::uint8_t>(9, 0), grey, {}),
               std::invalid_argument);
}

}  // namespace
}  // namespace angio
