// The reference raycaster against analytic expectations (rendering model).
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "core/reference_raycaster.h"
#include "core/view_geometry.h"
#include "core/volume_sampling.h"

namespace angio {
namespace {

constexpr double kSlabHu = 300;

// A TF that is transparent below `threshold` HU and a constant color/opacity from there on.
TransferFunction stepTf(double opacity, double threshold = 100) {
  const glm::vec3 color(1.f, 0.5f, 0.25f);
  TransferFunction tf;
  tf.points = {
      {-1024, color, 0}, {threshold - 1, color, 0}, {threshold, color, opacity}, {3071, color, opacity}};
  return tf;
}

RenderParams plainParams(double isd, double osd, Filter filter) {
  RenderParams p;
  p.sampling = {isd, osd, filter, 1.0};
  p.shading.enabled = false;
  return p;
}

// Trilinear with the default shading on, viewed at `angleDeg` about k.
RenderParams shadedParams(double isd, double osd, double angleDeg) {
  RenderParams p = plainParams(isd, osd, Filter::trilinear);
  p.shading.enabled = true;
  p.angleDeg = angleDeg;
  return p;
}

// 16 x 32 x 16 voxels of 1 mm; voxels with j in [8, 23] are a slab of kSlabHu, the rest air.
Volume slabVolume() {
  Volume v = makeVolume({16, 32, 16}, {1, 1, 1});
  for (int k = 0; k < 16; ++k)
    for (int j = 8; j <= 23; ++j)
      for (int i = 0; i < 16; ++i) v.voxels[v.indexOf(i, j, k)] = encodeVoxel(kSlabHu);
  return v;
}

glm::vec4 centrePixel(const Image& image) { return image.at(image.width / 2, image.height / 2); }

TEST(ReferenceRaycaster, SlabCompositesToPredictedOpacity) {
  // theta = 0 about k looks along +j through 16 voxels of slab: whatever osd, the ray crosses
  // 16 mm of material, so A = 1 - (1 - a)^16 and C = rgb * A (shading off).
  const Volume volume = slabVolume();
  const double a = 0.1;
  const TfTable table = buildTable(stepTf(a));
  for (double osd : {1.0, 0.5, 0.25}) {
    const Image image = renderReference(volume, table, plainParams(1.0, osd, Filter::nearest));
    const glm::vec4 p = centrePixel(image);
    const double expected = 1.0 - std::pow(1.0 - a, 16.0);
    EXPECT_NEAR(p.a, expected, 1e-5) << "osd " << osd;
    EXPECT_NEAR(p.r, expected * 1.0, 1e-5);
    EXPECT_NEAR(p.g, expected * 0.5, 1e-5);
    EXPECT_NEAR(p.b, expected * 0.25, 1e-5);
  }
}

TEST(ReferenceRaycaster, GradientAcrossTheViewGivesAmbientOnly) {
  // HU = 300 + 10 i everywhere: the gradient (10 HU/mm along i) is perpendicular to the view
  // direction (+j), so every sample gets s = ka + kd * 0 = ka.
  Volume volume = makeVolume({16, 32, 16}, {1, 1, 1});
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 16; ++i) volume.voxels[volume.indexOf(i, j, k)] = encodeVoxel(300 + 10 * i);
  const TfTable table = buildTable(stepTf(0.05));
  RenderParams shaded = plainParams(1.0, 1.0, Filter::nearest);
  shaded.shading = {true, 0.3, 0.7};
  const glm::vec4 plain =
      centrePixel(renderReference(volume, table, plainParams(1.0, 1.0, Filter::nearest)));
  const glm::vec4 dim = centrePixel(renderReference(volume, table, shaded));
  EXPECT_NEAR(dim.r, 0.3 * plain.r, 1e-5);
  EXPECT_NEAR(dim.a, plain.a, 1e-6);  // shading changes color, never opacity
}

TEST(ReferenceRaycaster, HeadlightOnFacingSurfaceIsFullyLit) {
  // The slab's front face has its gradient along the view direction: s = ka + kd = 1 there.
  const Volume volume = slabVolume();
  const TfTable table = buildTable(stepTf(1.0));  // opaque: only the first sample counts
  RenderParams shaded = plainParams(1.0, 1.0, Filter::nearest);
  shaded.shading = {true, 0.3, 0.7};
  const glm::vec4 p = centrePixel(renderReference(volume, table, shaded));
  EXPECT_NEAR(p.r, 1.0, 1e-5);
  EXPECT_NEAR(p.a, 1.0, 1e-6);
}

TEST(ReferenceRaycaster, EarlyRayTerminationStopsAtThreshold) {
  const Volume volume = slabVolume();
  const double a = 0.1;
  const TfTable table = buildTable(stepTf(a));
  RenderParams p = plainParams(1.0, 1.0, Filter::nearest);
  p.sampling.ert = 0.5;
  // First n with 1 - 0.9^n >= 0.5 is n = 7.
  const glm::vec4 pixel = centrePixel(renderReference(volume, table, p));
  EXPECT_NEAR(pixel.a, 1.0 - std::pow(0.9, 7), 1e-5);
}

TEST(ReferenceRaycaster, MipShowsKnownMaximumThroughWindow) {
  Volume volume = makeVolume({9, 9, 9}, {1, 1, 1}, encodeVoxel(0));
  for (int k = 3; k <= 5; ++k)
    for (int i = 3; i <= 5; ++i) volume.voxels[volume.indexOf(i, 6, k)] = encodeVoxel(500);
  RenderParams p = plainParams(1.0, 0.5, Filter::nearest);
  p.compositing = Compositing::mip;
  p.mip = {1000, 0};  // grey = (HU + 500) / 1000
  const Image image = renderReference(volume, buildTable(stepTf(0.5)), p);
  // theta = 0: rays along +j; the pixel nearest (i, k) = (4, 4) sees the hot 3 x 3 patch.
  const ViewGeometry view = makeViewGeometry(volume, p);
  const int x = int(std::floor(view.width / 2.0 - 0.5 + (4.0 - view.centre.x) / view.pixelMm + 0.5));
  const int y = int(std::floor(view.height / 2.0 - 0.5 - (4.0 - view.centre.z) / view.pixelMm + 0.5));
  EXPECT_NEAR(image.at(x, y).r, 1.0, 1e-6);
  EXPECT_NEAR(image.at(2, y).r, 0.5, 1e-6);  // beside the patch the maximum is 0 HU
  EXPECT_EQ(image.at(0, y).r, 0.f);          // a ray that misses the volume stays black
}

// Ball of radius r mm, opaque, in a 48^3 volume with anisotropic spacing.
Volume ballVolume(double radiusMm, glm::dvec3 spacing) {
  Volume v = makeVolume({48, 48, 48}, spacing);
  const glm::dvec3 centre = domainExtent(v) * 0.5;
  for (int k = 0; k < 48; ++k)
    for (int j = 0; j < 48; ++j)
      for (int i = 0; i < 48; ++i)
        if (glm::length(glm::dvec3(i, j, k) * spacing - centre) <= radiusMm)
          v.voxels[v.indexOf(i, j, k)] = encodeVoxel(kSlabHu);
  return v;
}

int opaqueRunInRow(const Image& image, int y) {
  int count = 0;
  for (int x = 0; x < image.width; ++x) count += image.at(x, y).a > 0.5f;
  return count;
}

TEST(ReferenceRaycaster, SphereSilhouetteWidthMatchesDiameterOnEveryAxisAndAngle) {
  const double radius = 15.0;
  const Volume volume = ballVolume(radius, {0.8, 0.9, 1.0});
  // Threshold halfway between air and ball: the iso-surface lies midway between the last voxel
  // inside and the first outside, so the silhouette is within a voxel (<= 1 mm) of the diameter.
  const TfTable table = buildTable(stepTf(1.0, (-1024 + kSlabHu) / 2));
  for (Axis axis : {Axis::i, Axis::j, Axis::k})
    for (double angle : {0.0, 30.0, 125.0}) {
      RenderParams p = plainParams(0.5, 0.5, Filter::trilinear);
      p.axis = axis;
      p.angleDeg = angle;
      const Image image = renderReference(volume, table, p);
      const double pixel = makeViewGeometry(volume, p).pixelMm;
      // Voxelisation moves each edge by up to half a voxel (0.5 mm); pixels quantise by 0.5 mm.
      EXPECT_NEAR(opaqueRunInRow(image, image.height / 2) * pixel, 2 * radius, 2.0)
          << "axis " << toString(axis) << " angle " << angle;
    }
}

TEST(ReferenceRaycaster, FullTurnGivesIdenticalBytes) {
  const Volume volume = ballVolume(12.0, {1, 1, 1});
  const TfTable table = buildTable(stepTf(0.3));
  RenderParams p = shadedParams(1.0, 1.0, 33);
  const auto first = toRgb8(renderReference(volume, table, p));
  p.angleDeg = 33 + 360;
  EXPECT_EQ(first, toRgb8(renderReference(volume, table, p)));
}

TEST(ReferenceRaycaster, HalvingIsdDoublesImageSize) {
  const Volume volume = ballVolume(10.0, {0.7, 0.7, 1.3});
  RenderParams p = plainParams(1.0, 1.0, Filter::nearest);
  const ViewGeometry coarse = makeViewGeometry(volume, p);
  p.sampling.isd = 0.5;
  const ViewGeometry fine = makeViewGeometry(volume, p);
  // W = ceil(x) -> ceil(2x) lies in [2W - 1, 2W].
  EXPECT_GE(fine.width, 2 * coarse.width - 1);
  EXPECT_LE(fine.width, 2 * coarse.width);
  EXPECT_GE(fine.height, 2 * coarse.height - 1);
  EXPECT_LE(fine.height, 2 * coarse.height);
  const Image image = renderReference(volume, buildTable(stepTf(0.5)), p);
  EXPECT_EQ(image.width, fine.width);
  EXPECT_EQ(image.height, fine.height);
}

TEST(ReferenceRaycaster, SameBytesWhateverTheThreadCount) {
  const Volume volume = ballVolume(14.0, {0.8, 0.8, 1.0});
  const TfTable table = buildTable(stepTf(0.2));
  const RenderParams p = shadedParams(0.7, 0.3, 17);
  Pixels oneThread;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    oneThread = renderReference(volume, table, p).pixels;
  }
  const Pixels manyThreads = renderReference(volume, table, p).pixels;
  ASSERT_EQ(oneThread.size(), manyThreads.size());
  EXPECT_EQ(0, std::memcmp(oneThread.data(), manyThreads.data(), oneThread.size() * sizeof(glm::vec4)));
}

// Rendering-model orientation: theta = 0 about k is the anterior view (patient's left on image
// right, head up); theta = 90 looks along -i (from the patient's left), posterior on image right.
TEST(ReferenceRaycaster, AnteriorViewPutsPatientLeftRightAndHeadUp) {
  Volume volume = makeVolume({20, 20, 20}, {1, 1, 1});
  for (int k = 15; k < 19; ++k)  // a marker at high i (left), high j (posterior), high k (superior)
    for (int j = 15; j < 19; ++j)
      for (int i = 15; i < 19; ++i) volume.voxels[volume.indexOf(i, j, k)] = encodeVoxel(kSlabHu);
  const TfTable table = buildTable(stepTf(1.0));
  RenderParams p = plainParams(1.0, 1.0, Filter::nearest);
  auto markerCentre = [&](const Image& image) {
    glm::dvec2 sum(0.0);
    int count = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        if (image.at(x, y).a > 0.5f) sum += glm::dvec2(x, y), ++count;
    return sum / double(count);
  };
  const Image anterior = renderReference(volume, table, p);
  const glm::dvec2 a = markerCentre(anterior);
  EXPECT_GT(a.x, anterior.width / 2.0);   // left on image right
  EXPECT_LT(a.y, anterior.height / 2.0);  // superior up
  p.angleDeg = 90;
  const Image lateral = renderReference(volume, table, p);
  EXPECT_GT(markerCentre(lateral).x, lateral.width / 2.0);  // posterior on image right
}

TEST(VolumeSampling, FiltersReproduceALinearRamp) {
  // d = 100 + 3i + 5j + 7k: trilinear is exact, the mean of a voxel and its face neighbours is
  // the voxel's value (inside), central differences give the slope per mm.
  const glm::dvec3 spacing(0.5, 1.0, 2.0);
  Volume v = makeVolume({10, 10, 10}, spacing);
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 10; ++i)
        v.voxels[v.indexOf(i, j, k)] = encodeVoxel(100 + 3 * i + 5 * j + 7 * k - kHuOffset);
  const glm::dvec3 q(3.25, 4.5, 6.75);
  const double expected = 100 + 3 * q.x + 5 * q.y + 7 * q.z;
  EXPECT_NEAR(sampleDensity(v, q, Filter::trilinear), expected, 1e-3);
  EXPECT_NEAR(sampleDensity(v, q, Filter::nearest), 100 + 3 * 3 + 5 * 5 + 7 * 7, 1e-6);
  EXPECT_NEAR(sampleDensity(v, q, Filter::mean), 100 + 3 * 3 + 5 * 5 + 7 * 7, 1e-4);
  const glm::vec3 g = sampleGradient(v, q, Filter::trilinear);
  EXPECT_NEAR(g.x, 3 / spacing.x, 1e-4);
  EXPECT_NEAR(g.y, 5 / spacing.y, 1e-4);
  EXPECT_NEAR(g.z, 7 / spacing.z, 1e-4);
}

TEST(ViewGeometry, SamplesStayInsideTheDomain) {
  const Volume volume = makeVolume({17, 23, 11}, {0.9, 0.7, 1.4});
  RenderParams p;
  p.angleDeg = 47;
  p.sampling.osd = 0.37;
  const ViewGeometry view = makeViewGeometry(volume, p);
  const glm::dvec3 extent = domainExtent(volume);
  for (int y = 0; y < view.height; y += 3)
    for (int x = 0; x < view.width; x += 3) {
      const glm::dvec3 o = view.rayOrigin(x, y);
      const SampleRange range = sampleRange(view, o);
      for (long k : {range.first, range.last}) {
        if (range.empty()) break;
        const glm::dvec3 point = o + double(k) * view.sampleMm * view.viewDir;
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(point, glm::dvec3(-1e-6))) &&
                    glm::all(glm::lessThanEqual(point, extent + 1e-6)));
        // One step further out is outside.
        const long outer = k == range.first ? k - 1 : k + 1;
        const glm::dvec3 beyond = o + double(outer) * view.sampleMm * view.viewDir;
        EXPECT_FALSE(glm::all(glm::greaterThanEqual(beyond, glm::dvec3(1e-6))) &&
                     glm::all(glm::lessThanEqual(beyond, extent - 1e-6)));
      }
    }
}

}  // namespace
}  // namespace angio
