// The realistic phantom against published CT statistics: noise of 15-25 HU with a lag-1
// autocorrelation of 0.45-0.65 in-plane, arterial-phase (and portal-venous) organ and vessel densities, textured cancellous bone
// and fatty marrow, far more tissue on the "CTA vessels" ramp than the simple phantom, correct
// ground-truth labels and the same bytes for any thread count; the simple style unchanged.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "core/labels.h"
#include "core/volume.h"
#include "phantom/phantom.h"

namespace angio {
namespace {

// 1.6 mm in-plane, 2 mm slices: fine enough to sample inside organs and the renal cortex.
constexpr glm::ivec3 kDims{256, 256, 600};

PhantomOptions realistic(glm::ivec3 dims, bool labels = false) {
  return {.dims = dims, .seed = 1, .groundTruthLabels = labels, .style = PhantomStyle::realistic};
}

// Anatomy frame (phantom_anatomy.h) to physical: the top of the box is at z = 0.
glm::dvec3 physical(double x, double y, double zAnatomy) { return {x, y, zAnatomy - 1200}; }

glm::ivec3 voxelOf(const Volume& volume, glm::dvec3 physicalMm) {
  return glm::ivec3(glm::floor(physicalToIndex(volume, physicalMm) + 0.5));
}

double huOf(const Volume& volume, glm::ivec3 v) { return huOfDensity(volume.densityAt(v.x, v.y, v.z)); }

// HU of the voxels within halfMm (per axis) of an anatomy-frame point.
std::vector<double> huAround(const Volume& volume, glm::dvec3 anatomy, glm::dvec3 halfMm) {
  const glm::ivec3 lo = voxelOf(volume, physical(anatomy.x, anatomy.y, anatomy.z) - halfMm);
  const glm::ivec3 hi = voxelOf(volume, physical(anatomy.x, anatomy.y, anatomy.z) + halfMm);
  std::vector<double> values;
  for (int k = lo.z; k <= hi.z; ++k)
    for (int j = lo.y; j <= hi.y; ++j)
      for (int i = lo.x; i <= hi.x; ++i) values.push_back(huOf(volume, {i, j, k}));
  return values;
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

double standardDeviation(const std::vector<double>& values) {
  double sum = 0, sum2 = 0;
  for (double v : values) sum += v, sum2 += v * v;
  const double mean = sum / values.size();
  return std::sqrt(sum2 / values.size() - mean * mean);
}

// Noise statistics in a homogeneous box of one slice range: standard deviation and the
// autocorrelation between neighbours along i.
struct NoiseStats {
  double sigma = 0;
  double lag1 = 0;
};

NoiseStats noiseIn(const Volume& volume, glm::dvec3 anatomy, glm::dvec3 halfMm) {
  const glm::ivec3 lo = voxelOf(volume, physical(anatomy.x, anatomy.y, anatomy.z) - halfMm);
  const glm::ivec3 hi = voxelOf(volume, physical(anatomy.x, anatomy.y, anatomy.z) + halfMm);
  const double mean = [&] {
    const std::vector<double> v = huAround(volume, anatomy, halfMm);
    double s = 0;
    for (double x : v) s += x;
    return s / v.size();
  }();
  double var = 0, cov = 0;
  std::size_t n = 0, pairs = 0;
  for (int k = lo.z; k <= hi.z; ++k)
    for (int j = lo.y; j <= hi.y; ++j)
      for (int i = lo.x; i <= hi.x; ++i) {
        const double a = huOf(volume, {i, j, k}) - mean;
        var += a * a, ++n;
        if (i < hi.x) cov += a * (huOf(volume, {i + 1, j, k}) - mean), ++pairs;
      }
  return {std::sqrt(var / n), (cov / pairs) / (var / n)};
}

class RealisticPhantom : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { phantom_ = new Phantom(generatePhantom(realistic(kDims, true))); }
  static void TearDownTestSuite() {
    delete phantom_;
    phantom_ = nullptr;
  }
  const Volume& volume() const { return phantom_->volume; }
  int labelAt(double x, double y, double z) const {
    const glm::ivec3 v = voxelOf(volume(), physical(x, y, z));
    return labelOf(volume().at(v.x, v.y, v.z));
  }
  static Phantom* phantom_;
};
Phantom* RealisticPhantom::phantom_ = nullptr;

TEST_F(RealisticPhantom, NoiseIsCorrelatedWithinTheClinicalBand) {
  // In the table's foam pad (uniform, no texture, no vessels): only noise varies there. The noise
  // is additive, the same in soft tissue.
  const NoiseStats stats = noiseIn(volume(), {0, 133, 600}, {30, 6, 20});
  std::printf("table pad: noise sigma %.1f HU, lag-1 autocorrelation %.2f\n", stats.sigma, stats.lag1);
  EXPECT_GE(stats.sigma, 15);
  EXPECT_LE(stats.sigma, 25);
  EXPECT_GE(stats.lag1, 0.45);
  EXPECT_LE(stats.lag1, 0.65);
}

TEST_F(RealisticPhantom, OrgansReadTheirArterialPhaseDensities) {
  EXPECT_NEAR(median(huAround(volume(), {-65, 0, 1175}, {12, 12, 12})), 95, 10) << "liver";
  EXPECT_NEAR(median(huAround(volume(), {95, 15, 1195}, {4, 4, 4})), 118, 15) << "spleen";
  EXPECT_NEAR(median(huAround(volume(), {45, 7, 1182}, {2, 2, 2})), 125, 25) << "pancreas";
  EXPECT_NEAR(median(huAround(volume(), {0, -5, 905}, {15, 10, 10})), 10, 8) << "bladder";
  EXPECT_NEAR(median(huAround(volume(), {35, 43, 1140}, {4, 4, 6})), 60, 10) << "psoas";
  for (double s : {1.0, -1.0}) {
    // Medulla in the middle, cortex 3.5 mm inside the lateral surface: cortex 150-200, medulla ~100.
    EXPECT_NEAR(median(huAround(volume(), {72 * s, 52, 1160}, {4, 4, 6})), 100, 15) << "medulla " << s;
    EXPECT_NEAR(median(huAround(volume(), {98.5 * s, 52, 1160}, {0.5, 2, 6})), 175, 25)
        << "cortex " << s;
  }
}

// The cava (right of the aorta) and a femoral vein (beside its artery): unenhanced in this phase.
constexpr glm::dvec3 kCava{-14, 10, 1140}, kFemoralVein{74, -9.5, 750};

TEST_F(RealisticPhantom, VeinsAreNotYetEnhanced) {
  EXPECT_LT(median(huAround(volume(), kCava, {4, 4, 6})), 90) << "cava";
  EXPECT_LT(median(huAround(volume(), kFemoralVein, {2, 2, 4})), 90) << "femoral vein";
}

TEST_F(RealisticPhantom, CancellousBoneIsTexturedAndLongBoneMarrowFatty) {
  const std::vector<double> vertebra = huAround(volume(), {0, 40, 1121}, {10, 8, 6});  // L3's body
  EXPECT_GE(median(vertebra), 200);
  EXPECT_LE(median(vertebra), 400);
  const double spread = standardDeviation(vertebra);
  EXPECT_GE(spread, 50) << "trabecular texture plus noise";
  EXPECT_LE(spread, 150);
  for (double s : {1.0, -1.0}) {
    EXPECT_NEAR(median(huAround(volume(), {111 * s, 36, 720}, {3, 3, 10})), -40, 25)
        << "femur marrow " << s;
  }
}

TEST_F(RealisticPhantom, LabelsStayCorrect) {
  EXPECT_EQ(labelAt(0, 40, 1121), kBoneLabel);  // trabecular core
  for (double s : {1.0, -1.0}) {
    EXPECT_EQ(labelAt(111 * s, 36, 720), kBoneLabel) << "fatty marrow " << s;
    EXPECT_EQ(labelAt((111 + 12) * s, 36, 720), kBoneLabel) << "cortex " << s;
    EXPECT_EQ(labelAt(72 * s, 52, 1160), 0) << "kidney " << s;
  }
  EXPECT_EQ(labelAt(-65, 0, 1175), 0) << "liver";
  EXPECT_EQ(labelAt(0, -5, 905), 0) << "bladder";
  std::size_t points = 0, labelled = 0;
  for (const CenterlinePath& path : phantom_->centerlines.paths) {
    for (const CenterlinePoint& point : path.points) {
      const glm::ivec3 v = voxelOf(volume(), point.positionMm);
      ++points;
      labelled += labelOf(volume().at(v.x, v.y, v.z)) != 0;
    }
  }
  EXPECT_GT(points, 1000u);
  EXPECT_EQ(labelled, 0u);
}

// The same anatomy ~70 s after the injection (published portal-venous values): the liver 100-130 HU,
// the spleen homogeneous, the kidneys nephrographic, the aorta down to 150-185 HU and the veins
// enhanced: vessels and organs all on the vessel presets' ramp.
TEST(PortalVenousPhantom, OrgansAndVesselsReadPortalVenousDensities) {
  const Volume volume =
      generatePhantom({.dims = kDims, .seed = 1, .style = PhantomStyle::portalVenous}).volume;
  EXPECT_NEAR(median(huAround(volume, {-65, 0, 1175}, {12, 12, 12})), 115, 10) << "liver";
  EXPECT_NEAR(median(huAround(volume, {95, 15, 1195}, {4, 4, 4})), 120, 12) << "spleen";
  for (double s : {1.0, -1.0}) {
    EXPECT_NEAR(median(huAround(volume, {72 * s, 52, 1160}, {4, 4, 6})), 165, 15) << "medulla " << s;
  }
  EXPECT_NEAR(median(huAround(volume, {14, 5, 1150}, {4, 4, 6})), 183, 15) << "aorta";
  EXPECT_NEAR(median(huAround(volume, kCava, {4, 4, 6})), 150, 15) << "cava";
  EXPECT_NEAR(median(huAround(volume, kFemoralVein, {2, 2, 4})), 130, 20) << "femoral vein";
  EXPECT_NEAR(median(huAround(volume, {-12, -1, 1182}, {3, 3, 3})), 180, 20) << "portal vein";
}

// Fraction of the 8x8 pixel tiles of the axial slices in which some voxel reaches minHu: the tiles
// a renderer cannot skip under a TF that starts there.
double tilesReaching(const Volume& volume, double minHu, int k0, int k1) {
  const int level = densityOfHu(minHu);
  std::size_t tiles = 0, reaching = 0;
  for (int k = k0; k < k1; ++k)
    for (int j0 = 0; j0 < volume.dims.y; j0 += 8)
      for (int i0 = 0; i0 < volume.dims.x; i0 += 8) {
        ++tiles;
        bool reaches = false;
        for (int j = j0; j < std::min(j0 + 8, volume.dims.y) && !reaches; ++j)
          for (int i = i0; i < std::min(i0 + 8, volume.dims.x) && !reaches; ++i)
            reaches = volume.densityAt(i, j, k) >= level;
        reaching += reaches;
      }
  return double(reaching) / tiles;
}

TEST(PhantomStyles, RealisticTissueReachesTheVesselPresetsRamp) {
  // "CTA vessels" rises from 0 opacity at 140 HU: real CT has organs, trabecular bone, small
  // vessels, partial volume and noise tails there, which empty-space skipping cannot skip.
  const glm::ivec3 dims{256, 256,
                        600};  // 12.8 mm tiles, as the renderer's 8x8 tiles at 512^2 are 6.4 mm
  const Volume simple = generatePhantom({.dims = dims, .style = PhantomStyle::simple}).volume;
  const Volume real = generatePhantom(realistic(dims)).volume;
  // The abdomen and pelvis: the top 300 mm of the box.
  const int abdomen = dims.z * 3 / 4;
  const double simpleTiles = tilesReaching(simple, 140, abdomen, dims.z);
  const double realTiles = tilesReaching(real, 140, abdomen, dims.z);
  std::printf(
      "abdomen, 8x8 tiles reaching 140 HU: simple %.2f %%, realistic %.2f %%; whole: %.2f %%, %.2f %%\n",
      100 * simpleTiles, 100 * realTiles, 100 * tilesReaching(simple, 140, 0, dims.z),
      100 * tilesReaching(real, 140, 0, dims.z));
  EXPECT_GT(realTiles, 1.3 * simpleTiles);
}

TEST(PhantomStyles, RealisticIsTheSameForAnyThreadCount) {
  const glm::ivec3 dims{48, 48, 120};
  std::vector<Voxel> single, dual;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    single = generatePhantom(realistic(dims, true)).volume.voxels;
  }
  {
    tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
    dual = generatePhantom(realistic(dims, true)).volume.voxels;
  }
  EXPECT_TRUE(single == dual);
  EXPECT_FALSE(generatePhantom({.dims = dims, .style = PhantomStyle::simple}).volume.voxels == single);
}

std::uint64_t fnv1a(const std::vector<Voxel>& voxels) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (Voxel v : voxels) {
    h = (h ^ (v & 0xff)) * 0x100000001b3ull;
    h = (h ^ (v >> 8)) * 0x100000001b3ull;
  }
  return h;
}

TEST(PhantomStyles, SimpleIsThePreviousGeneratorsBytes) {
  // The checksum of the generator before the realistic style existed (same voxels byte for byte,
  // checked against that build's `angioray phantom` output), labels included.
  const Phantom simple = generatePhantom(
      {.dims = {48, 48, 112}, .seed = 1, .groundTruthLabels = true, .style = PhantomStyle::simple});
  EXPECT_EQ(fnv1a(simple.volume.voxels), 11104049205866604550ull);
}

TEST(PhantomStyles, ParseByName) {
  EXPECT_EQ(parsePhantomStyle("realistic"), PhantomStyle::realistic);
  EXPECT_EQ(parsePhantomStyle("simple"), PhantomStyle::simple);
  EXPECT_EQ(parsePhantomStyle("portal-venous"), PhantomStyle::portalVenous);
  EXPECT_EQ(parsePhantomStyle("clean"), std::nullopt);
  EXPECT_EQ(PhantomOptions{}.style, PhantomStyle::realistic);
}

}  // namespace
}  // namespace angio
