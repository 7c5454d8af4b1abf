// Crop box, clip plane and thick slab (rendering model, "Crop, clip, slab"): the per-ray depth
// intervals against geometry worked out by hand, images of constant blocks against closed forms,
// and the fast raycaster against the reference with every kind of clipping.
#include <cmath>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "core/clip_interval.h"
#include "core/fast_raycaster.h"
#include "core/ray_pick.h"
#include "core/reference_raycaster.h"
#include "core/view_geometry.h"
#include "io/tf_file.h"
#include "phantom/phantom.h"
#include "tests/support/constant_opacity.h"
#include "tests/support/image_difference.h"
#include "tests/support/varying_regions.h"

namespace angio {
namespace {

using test_support::maxChannelDifference;

// Red, opacity a per voxel unit, from -900 HU up: a block of 0 HU shows everywhere.
TfTable constantTable(double opacity) { return test_support::constantTable(opacity, {1, 0, 0}); }

// A pixel's opacity is 1 - (1 - a)^n for its n samples.
RenderParams plain() { return test_support::plainParams(); }

double opacityOf(int samples, double a) { return 1 - std::pow(1 - a, samples); }

// 17^3 voxels of 1 mm: domain [0, 16]^3, centre 8. Theta = 0 about k: rays along +j, image right
// +i, so pixel x's ray has i = 8 + h and depth t = j - 8.
Volume block() { return makeVolume({17, 17, 17}, {1, 1, 1}, encodeVoxel(0)); }

TEST(ClipInterval, CropBoxCutsEachRayToItsSlabIntersection) {
  const Volume volume = block();
  RenderParams p = plain();
  p.clipping.crop = CropBox{{2, 5, 0}, {12, 9.5, 16}};
  const ViewGeometry view = makeViewGeometry(volume, p);
  const glm::dvec3 origin(6, 8, 8);  // t = j - 8: j in [5, 9.5] is t in [-3, 1.5]
  const DepthInterval inside = clipInterval(p.clipping, view, origin);
  EXPECT_DOUBLE_EQ(inside.begin, -3);
  EXPECT_DOUBLE_EQ(inside.end, 1.5);
  EXPECT_TRUE(clipInterval(p.clipping, view, {13, 8, 8}).empty());  // i = 13 is beyond the box
  // Samples t = -3 .. 1 (k * 1 mm with -3 <= t < 1.5).
  const SampleRange samples = clippedSampleRange(view, p.clipping, origin);
  EXPECT_EQ(samples.first, -3);
  EXPECT_EQ(samples.last, 1);
}

TEST(ClipInterval, SampleOnTheBeginIsInAndOnTheEndIsOut) {
  const Volume volume = block();
  RenderParams p = plain();
  p.clipping.slab = ThickSlab{1.0, 6.0};  // t in [-2, 4)
  const ViewGeometry view = makeViewGeometry(volume, p);
  const SampleRange samples = clippedSampleRange(view, p.clipping, view.centre);
  EXPECT_EQ(samples.first, -2);
  EXPECT_EQ(samples.last, 3);
  // The domain still bounds it: t from -8 to 8 only.
  p.clipping.slab = ThickSlab{0, 100};
  const SampleRange all = clippedSampleRange(view, p.clipping, view.centre);
  EXPECT_EQ(all.first, -8);
  EXPECT_EQ(all.last, 8);
}

TEST(ClipInterval, PlaneRemovesTheHalfSpaceOnItsNormalsSide) {
  const Volume volume = block();
  RenderParams p = plain();
  const ViewGeometry view = makeViewGeometry(volume, p);  // d = +j
  const glm::dvec3 origin(8, 8, 8);
  // Normal +j through j = 11: removes j > 11, keeps t < 3.
  p.clipping.plane = ClipPlane{false, 0, {0, 11, 0}, {0, 2, 0}};
  DepthInterval kept = clipInterval(p.clipping, view, origin);
  EXPECT_TRUE(std::isinf(kept.begin) && kept.begin < 0);
  EXPECT_DOUBLE_EQ(kept.end, 3);
  // Normal -j (towards the viewer): keeps j >= 11, t >= 3.
  p.clipping.plane->normal = {0, -1, 0};
  kept = clipInterval(p.clipping, view, origin);
  EXPECT_DOUBLE_EQ(kept.begin, 3);
  // Tilted 45 degrees in the i-j plane through the centre: n = (1, 1, 0) keeps i + j <= 16, so
  // the ray at i = 10 keeps j <= 6, t < -2.
  p.clipping.plane = ClipPlane{false, 0, {8, 8, 8}, {1, 1, 0}};
  EXPECT_NEAR(clipInterval(p.clipping, view, {10, 8, 8}).end, -2, 1e-12);
  // Parallel to the ray: all or nothing.
  p.clipping.plane = ClipPlane{false, 0, {8, 8, 8}, {1, 0, 0}};
  EXPECT_FALSE(clipInterval(p.clipping, view, {7, 8, 8}).empty());
  EXPECT_TRUE(clipInterval(p.clipping, view, {9, 8, 8}).empty());
}

TEST(ClipInterval, FacingPlaneAndSlabFollowTheView) {
  const Volume volume = block();
  for (double angle : {0.0, 37.0, 200.0}) {
    RenderParams p = plain();
    p.angleDeg = angle;
    p.clipping.plane = facingPlane(-2.5);
    p.clipping.slab = ThickSlab{1, 4};  // [-1, 3)
    const ViewGeometry view = makeViewGeometry(volume, p);
    const DepthInterval kept = clipInterval(p.clipping, view, view.rayOrigin(3, 5));
    EXPECT_DOUBLE_EQ(kept.begin, -1) << angle;
    EXPECT_DOUBLE_EQ(kept.end, 3) << angle;
    p.clipping.plane->offsetMm = 0.5;
    EXPECT_DOUBLE_EQ(clipInterval(p.clipping, view, view.rayOrigin(3, 5)).begin, 0.5) << angle;
  }
}

TEST(ClipInterval, ProblemsAreNamed) {
  ViewClipping clipping;
  EXPECT_EQ(clippingProblem(clipping), "");
  clipping.crop = CropBox{{0, 0, 5}, {1, 1, 4}};
  EXPECT_NE(clippingProblem(clipping).find("k minimum"), std::string::npos);
  clipping.crop.reset();
  clipping.plane = ClipPlane{false, 0, {}, {0, 0, 0}};
  EXPECT_NE(clippingProblem(clipping).find("normal"), std::string::npos);
  clipping.plane = ClipPlane{false, 0, {NAN, 0, 0}, {0, 0, 1}};
  EXPECT_NE(clippingProblem(clipping).find("non-finite"), std::string::npos);
  clipping.plane.reset();
  clipping.slab = ThickSlab{0, 0};
  EXPECT_NE(clippingProblem(clipping).find("thickness"), std::string::npos);
  clipping.slab = ThickSlab{INFINITY, 2};
  EXPECT_NE(clippingProblem(clipping).find("non-finite"), std::string::npos);
}

// A sphere of 0 HU (radius 6 mm) in the centre of air: symmetric about the plane i = 8.
Volume sphere() {
  Volume volume = makeVolume({17, 17, 17}, {1, 1, 1});
  for (int k = 0; k < 17; ++k)
    for (int j = 0; j < 17; ++j)
      for (int i = 0; i < 17; ++i)
        if (glm::length(glm::dvec3(i, j, k) - 8.0) <= 6)
          volume.voxels[volume.indexOf(i, j, k)] = encodeVoxel(0);
  return volume;
}

TEST(ClippedRendering, CropToHalfASymmetricSphereLeavesTheOtherHalfBlack) {
  const Volume volume = sphere();
  const TfTable table = constantTable(0.2);
  for (Compositing mode : {Compositing::dvr, Compositing::mip}) {
    RenderParams p = plain();
    p.compositing = mode;
    const Image whole = renderReference(volume, table, p);
    p.clipping.crop = CropBox{{0, 0, 0}, {8, 16, 16}};  // i <= 8: the left half
    const Image cropped = renderReference(volume, table, p);
    const ViewGeometry view = makeViewGeometry(volume, p);
    int shown = 0;
    for (int y = 0; y < view.height; ++y)
      for (int x = 0; x < view.width; ++x) {
        const double i = view.rayOrigin(x, y).x;
        if (i > 8) {
          EXPECT_EQ(cropped.at(x, y), glm::vec4(0.f)) << x << "," << y;
        } else {
          // The crop does not cut rays along j inside it; the mirrored pixel shows the same.
          EXPECT_EQ(cropped.at(x, y), whole.at(x, y)) << x << "," << y;
          const int mirror = view.width - 1 - x;
          EXPECT_NEAR(cropped.at(x, y).a, whole.at(mirror, y).a, 1e-6) << x << "," << y;
          shown += cropped.at(x, y).a > 0.5f;
        }
      }
    EXPECT_GT(shown, 20);  // the half sphere is there
  }
}

TEST(ClippedRendering, SlabThroughABlockGivesTheClosedFormOpacity) {
  const Volume volume = block();
  const double a = 0.1;
  const TfTable table = constantTable(a);
  // Samples at t = k mm; [offset - T/2, offset + T/2) holds n of them.
  struct Slab {
    double offsetMm, thicknessMm;
    int samples;
  };
  for (const Slab& slab : {Slab{0.25, 6.5, 7}, Slab{0, 4, 4}, Slab{-5.5, 1, 1}, Slab{8.5, 3, 2}}) {
    RenderParams p = plain();
    p.clipping.slab = ThickSlab{slab.offsetMm, slab.thicknessMm};
    const Image image = renderReference(volume, table, p);
    const ViewGeometry view = makeViewGeometry(volume, p);
    const glm::vec4 centre = image.at(view.width / 2, view.height / 2);
    EXPECT_NEAR(centre.a, opacityOf(slab.samples, a), 1e-5) << slab.offsetMm;
    EXPECT_NEAR(centre.r, centre.a, 1e-6);
  }
}

TEST(ClippedRendering, TiltedPlaneKeepsTheSamplesOnItsBackSide) {
  // Each ray's opacity is that of the samples the point test n . (p - point) <= 0 keeps.
  const Volume volume = block();
  const double a = 0.1;
  const TfTable table = constantTable(a);
  RenderParams p = plain();
  p.angleDeg = 20;
  const ClipPlane plane{false, 0, {7.3, 8.1, 6.6}, {0.4, 0.7, -0.3}};
  p.clipping.plane = plane;
  const Image image = renderReference(volume, table, p);
  const ViewGeometry view = makeViewGeometry(volume, p);
  for (int y = 0; y < view.height; y += 3)
    for (int x = 0; x < view.width; x += 3) {
      const glm::dvec3 origin = view.rayOrigin(x, y);
      const SampleRange domain = sampleRange(view, origin);
      int kept = 0;
      for (long k = domain.first; k <= domain.last; ++k)
        kept += glm::dot(plane.normal, origin + double(k) * view.viewDir - plane.pointMm) <= 0;
      EXPECT_NEAR(image.at(x, y).a, opacityOf(kept, a), 1e-5) << x << "," << y;
    }
}

// Both raycasters, ERT off, on the same clipped view.
void expectFastIsReference(const Volume& volume, const RegionTables& tables, const RenderParams& p,
                           const std::string& what) {
  const SliceTiles tiles = buildSliceTiles(volume, p.axis);
  const TileClassification classification(tiles, tables, p.compositing == Compositing::mip);
  const Image reference = renderReference(volume, tables, p);
  const Image fast = renderFast(volume, classification, tables, p);
  ASSERT_EQ(fast.pixels.size(), reference.pixels.size()) << what;
  EXPECT_LE(maxChannelDifference(fast, reference), 1.f / 255.f) << what;
  // Something shows, and something is cut away (some pixel differs from the unclipped image).
  RenderParams unclipped = p;
  unclipped.clipping = {};
  float brightest = 0.f;
  for (const glm::vec4& pixel : reference.pixels) brightest = std::max(brightest, pixel.r);
  EXPECT_GT(brightest, 0.2f) << what;
  EXPECT_GT(maxChannelDifference(renderReference(volume, tables, unclipped), reference), 0.1f) << what;
}

// Every kind of clipping, placed by fractions of the domain extent E (the phantom is a body of
// about 400 x 400 x 1200 mm whatever its voxel count), none on the sample grid.
std::vector<std::pair<std::string, ViewClipping>> clippings(glm::dvec3 E) {
  std::vector<std::pair<std::string, ViewClipping>> all;
  ViewClipping crop;
  crop.crop = CropBox{E * glm::dvec3(0.13, 0.21, 0.18), E * glm::dvec3(0.76, 0.87, 0.81)};
  all.push_back({"crop", crop});
  ViewClipping plane;
  plane.plane = ClipPlane{false, 0, E * glm::dvec3(0.48, 0.53, 0.45), {0.3, -0.8, 0.45}};
  all.push_back({"plane", plane});
  ViewClipping facing;
  facing.plane = facingPlane(-0.07 * E.x);
  all.push_back({"facing plane", facing});
  ViewClipping slab;
  slab.slab = ThickSlab{0.05 * E.x, 0.28 * E.x};
  all.push_back({"slab", slab});
  ViewClipping together = crop;
  together.plane = plane.plane;
  together.slab = ThickSlab{-0.08 * E.x, 0.6 * E.x};
  all.push_back({"crop+plane+slab", together});
  return all;
}

TEST(ClippedRendering, FastMatchesReferenceForEveryFilterAndMode) {
  const Volume volume =
      generatePhantom({.dims = {48, 48, 112}, .seed = 1, .style = PhantomStyle::simple}).volume;
  const TfTable table = buildTable(loadPresetOrFile("cta-vessels-bone"));
  int n = 0;
  for (const auto& [name, clipping] : clippings(domainExtent(volume)))
    for (Filter filter : {Filter::nearest, Filter::trilinear, Filter::mean})
      for (Compositing mode : {Compositing::dvr, Compositing::mip}) {
        RenderParams p;
        p.axis = n % 3 == 2 ? Axis::j : Axis::k;
        p.angleDeg = 13.0 + 47.0 * n++;
        p.sampling = qualitySampling(filter == Filter::trilinear ? Quality::high : Quality::medium);
        p.sampling.filter = filter;
        p.sampling.ert = 1.0;
        p.compositing = mode;
        p.clipping = clipping;
        expectFastIsReference(volume, singleTable(table), p,
                              name + " " + toString(filter) +
                                  (mode == Compositing::mip ? " mip" : " dvr") + " angle " +
                                  std::to_string(p.angleDeg));
      }
}

TEST(ClippedRendering, FastMatchesReferenceWithVesselGlyphRegionsAndACrop) {
  const Volume volume =
      generatePhantom({.dims = {48, 48, 112}, .seed = 1, .style = PhantomStyle::simple}).volume;
  const auto [focus, contextTable] = test_support::vesselRegionTables();
  for (Quality quality : {Quality::medium, Quality::high})
    for (double angle : {25.0, 160.0}) {
      RenderParams p;
      p.angleDeg = angle;
      p.sampling = qualitySampling(quality);
      p.sampling.ert = 1.0;
      p.clipping = clippings(domainExtent(volume))[quality == Quality::high ? 4 : 0].second;
      const ViewGeometry view = makeViewGeometry(volume, p);
      const RayRegions regions = test_support::varyingRegions(view, 5.f, 40, 7.3f, 60.f);
      expectFastIsReference(volume, RegionTables{&regions, &focus, &contextTable, nullptr}, p,
                            std::string("regions ") + toString(quality) + " " + std::to_string(angle));
    }
}

TEST(ClippedRendering, APickFindsTheFirstSampleBehindTheCut) {
  // Opacity 0.6 per sample: the first kept sample reaches the pick's 0.5.
  const Volume volume = block();
  const TfTable table = constantTable(0.6);
  RenderParams p = plain();
  const ViewGeometry view = makeViewGeometry(volume, p);
  const glm::dvec2 centre(view.width / 2.0, view.height / 2.0);
  const auto whole = pickPoint(volume, singleTable(table), p, centre, 0.5);
  ASSERT_TRUE(whole);
  EXPECT_DOUBLE_EQ(whole->positionMm.y, 0);  // the block's front face, t = -8
  p.clipping.plane = facingPlane(2.5);       // keeps t >= 2.5: the first sample is t = 3
  const auto cut = pickPoint(volume, singleTable(table), p, centre, 0.5);
  ASSERT_TRUE(cut);
  EXPECT_DOUBLE_EQ(cut->positionMm.y, 11);
}

TEST(ClippedRendering, FastImageIsTheSameBytesWithOneThread) {
  const Volume volume =
      generatePhantom({.dims = {48, 48, 112}, .seed = 1, .style = PhantomStyle::simple}).volume;
  const TfTable table = buildTable(loadPresetOrFile("cta-vessels-bone"));
  RenderParams p;
  p.angleDeg = 33;
  p.sampling = qualitySampling(Quality::high);
  p.clipping = clippings(domainExtent(volume))[4].second;
  const SliceTiles tiles = buildSliceTiles(volume, p.axis);
  const TileClassification classification(tiles, table);
  const Image parallel = renderFast(volume, classification, table, p);
  const tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
  const Image serial = renderFast(volume, classification, table, p);
  EXPECT_TRUE(parallel.pixels == serial.pixels);
}

}  // namespace
}  // namespace angio
