// Rendering with a TF per ray region (VesselGlyph's focus / context / outside): analytic cases
// and the fast raycaster against the reference with regions.
#include <cmath>

#include <gtest/gtest.h>

#include "core/fast_raycaster.h"
#include "phantom/phantom.h"
#include "core/reference_raycaster.h"
#include "core/view_geometry.h"
#include "tests/support/constant_opacity.h"
#include "tests/support/varying_regions.h"

namespace angio {
namespace {

using test_support::constantTable;

RenderParams plain() { return test_support::plainParams(); }

// Every ray gets the same intervals.
RayRegions sameForEveryRay(const ViewGeometry& view, std::vector<RegionInterval> intervals) {
  RayRegions regions;
  regions.width = view.width;
  regions.height = view.height;
  for (int n = 0; n < view.width * view.height; ++n) {
    regions.rayBegin.push_back(std::uint32_t(regions.intervals.size()));
    regions.intervals.insert(regions.intervals.end(), intervals.begin(), intervals.end());
  }
  regions.rayBegin.push_back(std::uint32_t(regions.intervals.size()));
  return regions;
}

TEST(RegionRendering, OnlyTheFocusIntervalIsRenderedWhenTheOutsideIsClipped) {
  // 17^3 voxels of 1 mm, all 0 HU (visible under the constant TFs). Theta = 0: rays along +j
  // through the centre, samples at t = -8 .. 8 mm. Focus [-2, 2) holds 4 samples: t = -2..1.
  const Volume volume = makeVolume({17, 17, 17}, {1, 1, 1}, encodeVoxel(0));
  const RenderParams p = plain();
  const ViewGeometry view = makeViewGeometry(volume, p);
  const RayRegions regions = sameForEveryRay(view, {{-2.f, 2.f, Region::focus}});
  const TfTable focus = constantTable(0.1, {1, 0, 0});
  const Image image = renderReference(volume, RegionTables{&regions, &focus, nullptr, nullptr}, p);
  const glm::vec4 centre = image.at(view.width / 2, view.height / 2);
  EXPECT_NEAR(centre.a, 1 - std::pow(0.9, 4), 1e-5);
  EXPECT_NEAR(centre.r, centre.a, 1e-6);
  EXPECT_EQ(centre.g, 0.f);
}

TEST(RegionRendering, EachRegionUsesItsOwnTf) {
  // Context [-6, -2) (4 samples, green, a = 0.2) in front of focus [-2, 2) (4 samples, red,
  // a = 0.1); the rest outside (blue, a = 0.05: 9 samples: -8, -7 and 2..8).
  const Volume volume = makeVolume({17, 17, 17}, {1, 1, 1}, encodeVoxel(0));
  const RenderParams p = plain();
  const ViewGeometry view = makeViewGeometry(volume, p);
  const RayRegions regions =
      sameForEveryRay(view, {{-6.f, -2.f, Region::context}, {-2.f, 2.f, Region::focus}});
  const TfTable focus = constantTable(0.1, {1, 0, 0});
  const TfTable context = constantTable(0.2, {0, 1, 0});
  const TfTable outside = constantTable(0.05, {0, 0, 1});
  const Image image = renderReference(volume, RegionTables{&regions, &focus, &context, &outside}, p);
  const glm::vec4 c = image.at(view.width / 2, view.height / 2);
  // Front to back: 2 outside, 4 context, 4 focus, 7 outside.
  double T = 1, r = 0, g = 0, b = 0;
  auto add = [&](int count, double alpha, double& channel) {
    for (int n = 0; n < count; ++n) channel += T * alpha, T *= 1 - alpha;
  };
  add(2, 0.05, b);
  add(4, 0.2, g);
  add(4, 0.1, r);
  add(7, 0.05, b);
  EXPECT_NEAR(c.r, r, 1e-5);
  EXPECT_NEAR(c.g, g, 1e-5);
  EXPECT_NEAR(c.b, b, 1e-5);
  EXPECT_NEAR(c.a, 1 - T, 1e-5);
}

TEST(RegionRendering, FastMatchesReferenceWithRegions) {
  const Volume volume =
      generatePhantom({.dims = {48, 48, 112}, .seed = 1, .style = PhantomStyle::simple}).volume;
  const auto [focusTable, contextTable] = test_support::vesselRegionTables();
  // The outside clipped; or the context clipped between a rendered focus and outside, so the
  // fast raycaster's leaps over clipped stretches start and end inside rays.
  const std::pair<const TfTable*, const TfTable*> contextAndOutside[] = {{&contextTable, nullptr},
                                                                         {nullptr, &contextTable}};
  for (Axis axis : {Axis::k, Axis::j})
    for (double angle : {20.0, 110.0})
      for (Quality quality : {Quality::medium, Quality::high})
        for (const auto& [contextTf, outsideTf] : contextAndOutside) {
          RenderParams p;
          p.axis = axis;
          p.angleDeg = angle;
          p.sampling = qualitySampling(quality);
          p.sampling.ert = 1.0;
          const ViewGeometry view = makeViewGeometry(volume, p);
          // Per-pixel intervals that vary across the image: focus around depth 0 with a width that
          // depends on x, a gap, context behind it.
          const RayRegions regions = test_support::varyingRegions(view, 5.f, 40, 7.3f, 60.f);
          const RegionTables tables{&regions, &focusTable, contextTf, outsideTf};
          const SliceTiles tiles = buildSliceTiles(volume, axis);
          const Image reference = renderReference(volume, tables, p);
          const Image fast = renderFast(volume, TileClassification(tiles, tables), tables, p);
          ASSERT_EQ(reference.pixels.size(), fast.pixels.size());
          float worst = 0.f, brightest = 0.f;
          for (std::size_t n = 0; n < fast.pixels.size(); ++n)
            for (int c = 0; c < 4; ++c) {
              worst = std::max(worst, std::abs(fast.pixels[n][c] - reference.pixels[n][c]));
              brightest = std::max(brightest, reference.pixels[n][c]);
            }
          EXPECT_LE(worst, 1.f / 255.f)
              << "axis " << toString(axis) << " angle " << angle << " quality " << int(quality)
              << (outsideTf ? " outside shown" : " outside clipped");
          EXPECT_GT(brightest, 0.2f);  // the regions render something
        }
}

}  // namespace
}  // namespace angio
