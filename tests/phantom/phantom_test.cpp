// The phantom: size and frame, determinism, ground-truth centerlines inside the lumen, the
// anatomy's landmarks (stenosis, horizontal runs, bones, air) and its visible fraction under the
// "CTA vessels" preset.
#include "phantom/phantom.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "core/transfer_function.h"
#include "core/volume.h"
#include "io/tf_file.h"

namespace angio {
namespace {

// Small sizes keep these fast; the anatomy is the same at any size, only coarser.
constexpr glm::ivec3 kSmallDims{96, 96, 240};
constexpr glm::ivec3 kMediumDims{128, 128, 300};

const Phantom& mediumPhantom() {
  static const Phantom phantom =
      generatePhantom({.dims = kMediumDims, .seed = 1, .style = PhantomStyle::simple});
  return phantom;
}

double huAt(const Volume& volume, glm::ivec3 index) {
  return huOfDensity(volume.densityAt(index.x, index.y, index.z));
}

glm::ivec3 voxelAtPoint(const Volume& volume, glm::dvec3 physical) {
  return glm::ivec3(glm::floor(physicalToIndex(volume, physical) + 0.5));
}

bool inside(const Volume& volume, glm::ivec3 index) {
  return glm::all(glm::greaterThanEqual(index, glm::ivec3(0))) &&
         glm::all(glm::lessThan(index, volume.dims));
}

// The largest HU within radiusMm of a physical point (voxel centres in a box around it).
double maxHuNear(const Volume& volume, glm::dvec3 physical, double radiusMm) {
  const glm::ivec3 lo =
      glm::max(glm::ivec3(glm::floor(physicalToIndex(volume, physical - radiusMm))), glm::ivec3(0));
  const glm::ivec3 hi =
      glm::min(glm::ivec3(glm::ceil(physicalToIndex(volume, physical + radiusMm))), volume.dims - 1);
  double best = -2000;
  for (int k = lo.z; k <= hi.z; ++k)
    for (int j = lo.y; j <= hi.y; ++j)
      for (int i = lo.x; i <= hi.x; ++i) best = std::max(best, huAt(volume, {i, j, k}));
  return best;
}

TEST(Phantom, HasTheRequestedDimsAndTheFixedPhysicalSize) {
  const Phantom phantom =
      generatePhantom({.dims = kSmallDims, .seed = 1, .style = PhantomStyle::simple});
  const Volume& volume = phantom.volume;
  EXPECT_EQ(volume.dims, kSmallDims);
  EXPECT_EQ(volume.voxels.size(), std::size_t(96) * 96 * 240);
  EXPECT_NEAR(volume.spacing.x, 409.6 / 96, 1e-12);
  EXPECT_NEAR(volume.spacing.y, 409.6 / 96, 1e-12);
  EXPECT_NEAR(volume.spacing.z, 1200.0 / 240, 1e-12);
  EXPECT_EQ(volume.direction, glm::dmat3(1.0));
  // x and y centred on the scanner axis.
  const glm::dvec3 centre = indexToPhysical(volume, glm::dvec3(volume.dims - 1) / 2.0);
  EXPECT_NEAR(centre.x, 0.0, 1e-9);
  EXPECT_NEAR(centre.y, 0.0, 1e-9);
}

TEST(Phantom, DefaultSpacingIsPointEightByOneMillimetre) {
  const PhantomOptions defaults;
  EXPECT_EQ(defaults.dims, glm::ivec3(512, 512, 1200));
  // The physical size does not depend on dims: check it through a small volume's extent.
  const Phantom phantom =
      generatePhantom({.dims = {64, 64, 100}, .seed = 1, .style = PhantomStyle::simple});
  const glm::dvec3 size = phantom.volume.spacing * glm::dvec3(phantom.volume.dims);
  EXPECT_NEAR(size.x / 512, 0.8, 1e-12);
  EXPECT_NEAR(size.z / 1200, 1.0, 1e-12);
}

TEST(Phantom, SameOptionsGiveTheSameBytes) {
  const Phantom a = generatePhantom({.dims = kSmallDims, .seed = 7, .style = PhantomStyle::simple});
  const Phantom b = generatePhantom({.dims = kSmallDims, .seed = 7, .style = PhantomStyle::simple});
  EXPECT_TRUE(a.volume.voxels == b.volume.voxels);
}

TEST(Phantom, ThreadCountDoesNotChangeTheBytes) {
  std::vector<Voxel> single, dual;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    single =
        generatePhantom({.dims = kSmallDims, .seed = 3, .style = PhantomStyle::simple}).volume.voxels;
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    dual = generatePhantom({.dims = kSmallDims, .seed = 3, .style = PhantomStyle::simple}).volume.voxels;
  }
  EXPECT_TRUE(single == dual);
}

TEST(Phantom, AnotherSeedChangesTheNoiseNotTheAnatomy) {
  const Phantom a = generatePhantom({.dims = kSmallDims, .seed = 1, .style = PhantomStyle::simple});
  const Phantom b = generatePhantom({.dims = kSmallDims, .seed = 2, .style = PhantomStyle::simple});
  std::size_t differing = 0;
  double sumAbsDifference = 0;
  for (std::size_t n = 0; n < a.volume.voxels.size(); ++n) {
    const int d = densityOf(a.volume.voxels[n]) - densityOf(b.volume.voxels[n]);
    differing += d != 0;
    sumAbsDifference += std::abs(d);
  }
  // Noise of sigma ~12 HU: most voxels differ, by about 2 * 12 / sqrt(pi) ~ 13.5 HU on average.
  EXPECT_GT(differing, a.volume.voxels.size() / 2);
  EXPECT_LT(sumAbsDifference / a.volume.voxels.size(), 25.0);
  ASSERT_EQ(a.centerlines.paths.size(), b.centerlines.paths.size());
  for (std::size_t p = 0; p < a.centerlines.paths.size(); ++p) {
    EXPECT_EQ(a.centerlines.paths[p].points.size(), b.centerlines.paths[p].points.size());
  }
}

TEST(Phantom, HasFourRootToLeafPathsSharingTheAorta) {
  const Phantom& phantom = mediumPhantom();
  std::vector<std::string> names;
  for (const CenterlinePath& path : phantom.centerlines.paths) names.push_back(path.name);
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names,
            (std::vector<std::string>{"aorta-left-anterior-tibial", "aorta-left-posterior-tibial",
                                      "aorta-right-anterior-tibial", "aorta-right-posterior-tibial"}));
  for (const CenterlinePath& path : phantom.centerlines.paths) {
    ASSERT_GT(path.points.size(), 1000u) << path.name;
    // Starts in the aorta at the top (radius ~10 mm), ends in a ~1.5 mm tibial branch at the foot.
    EXPECT_NEAR(path.points.front().radiusMm, 10.5, 0.5) << path.name;
    EXPECT_NEAR(path.points.back().radiusMm, 1.5, 0.2) << path.name;
    EXPECT_GT(path.points.front().positionMm.z, path.points.back().positionMm.z + 1000);
    for (std::size_t n = 1; n < path.points.size(); ++n) {
      const double step = glm::length(path.points[n].positionMm - path.points[n - 1].positionMm);
      EXPECT_GT(step, 0.5) << path.name << " point " << n;
      EXPECT_LT(step, 1.5) << path.name << " point " << n;
    }
    // The shared trunk is repeated: all paths begin at the same point.
    EXPECT_EQ(path.points.front().positionMm,
              phantom.centerlines.paths.front().points.front().positionMm);
  }
}

TEST(Phantom, CenterlinesLieInsideTheContrastFilledLumen) {
  // At 128 x 128 x 300 (3.2 x 3.2 x 4 mm voxels) the nearest voxel of a point on a 1.5 mm tibial
  // can be 3 mm away, beyond its lumen; partial volume still lifts most of them into the lumen
  // range (the blend ramp is one voxel wide), so 95% per path must hold.
  const Phantom& phantom = mediumPhantom();
  for (const CenterlinePath& path : phantom.centerlines.paths) {
    std::size_t inLumen = 0;
    for (const CenterlinePoint& point : path.points) {
      const glm::ivec3 voxel = voxelAtPoint(phantom.volume, point.positionMm);
      ASSERT_TRUE(inside(phantom.volume, voxel)) << path.name;
      const double hu = huAt(phantom.volume, voxel);
      inLumen += hu >= 150 && hu <= 700;  // lumen 330..430 HU plus noise and partial volume
    }
    EXPECT_GE(double(inLumen) / path.points.size(), 0.95) << path.name;
  }
}

TEST(Phantom, TheAortaIsFullyOpacified) {
  // Where the lumen is several voxels wide the nearest voxel is pure contrast.
  const Phantom& phantom = mediumPhantom();
  for (const CenterlinePoint& point : phantom.centerlines.paths.front().points) {
    if (point.radiusMm < 8) break;
    const double hu = huAt(phantom.volume, voxelAtPoint(phantom.volume, point.positionMm));
    EXPECT_GT(hu, 330);
    EXPECT_LT(hu, 500);
  }
}

TEST(Phantom, OneFemoralArteryHasAStenosisToFortyPercent) {
  const Phantom& phantom = mediumPhantom();
  int stenosedPaths = 0;
  for (const CenterlinePath& path : phantom.centerlines.paths) {
    // Radius ratio to the point 20 mm upstream: ~1 elsewhere (slow taper), 0.4 in the stenosis.
    double lowestRatio = 1;
    for (std::size_t n = 20; n < path.points.size(); ++n) {
      if (path.points[n].positionMm.z < 500 - 1200) break;  // above the knee: femoral and up
      lowestRatio = std::min(lowestRatio, path.points[n].radiusMm / path.points[n - 20].radiusMm);
    }
    if (lowestRatio < 0.5) {
      ++stenosedPaths;
      EXPECT_NEAR(lowestRatio, 0.4, 0.05) << path.name;
      EXPECT_NE(path.name.find("left"), std::string::npos) << path.name;
    }
  }
  EXPECT_EQ(stenosedPaths, 2);  // the left femoral is shared by both left paths
}

TEST(Phantom, SomeSegmentsRunNearlyHorizontally) {
  // A run of 30 mm along a path that drops less than a third of its length (< ~20 degrees).
  const Phantom& phantom = mediumPhantom();
  for (const CenterlinePath& path : phantom.centerlines.paths) {
    bool found = false;
    for (std::size_t n = 30; n < path.points.size() && !found; ++n) {
      const glm::dvec3 d = path.points[n].positionMm - path.points[n - 30].positionMm;
      found = std::abs(d.z) < glm::length(d) / 3;
    }
    EXPECT_TRUE(found) << path.name;
  }
}

TEST(Phantom, CtaVesselsPresetShowsOneToTwoPercentOfVoxels) {
  // A real peripheral run-off CTA shows one to two percent of its voxels under such a preset
  // (lumen, cancellous bone, kidneys, edges of cortical bone); coarser volumes a little more
  // (partial-volume edges are two voxels wide, so wider in mm). Checked here at half size.
  const TfTable table = buildTable(loadPresetOrFile("cta-vessels"));
  ASSERT_FALSE(table.anyVisible(densityOfHu(0), densityOfHu(130)));
  ASSERT_TRUE(table.anyVisible(densityOfHu(400), densityOfHu(400)));
  const Volume volume =
      generatePhantom({.dims = {256, 256, 600}, .seed = 1, .style = PhantomStyle::simple}).volume;
  std::size_t visible = 0;
  for (Voxel v : volume.voxels) visible += table.rgba[densityOf(v)].a > 0.f;
  const double fraction = double(visible) / volume.voxels.size();
  EXPECT_GE(fraction, 0.01);
  EXPECT_LE(fraction, 0.02);
}

TEST(Phantom, FemursAreCorticalBoneInTheThighs) {
  // Mid-shaft of each femur: 720 mm above the soles, ~111 mm from the midline, cortex 1500 HU.
  const Phantom phantom =
      generatePhantom({.dims = kSmallDims, .seed = 1, .style = PhantomStyle::simple});
  const double z = 720 - 1200;  // physical z: the top of the box is at 0
  for (double side : {1.0, -1.0}) {
    EXPECT_GT(maxHuNear(phantom.volume, {111 * side, 36, z}, 12), 1000) << side;
    // ... and not in the thigh's muscle in front of it (lateral to the femoral artery).
    EXPECT_LT(maxHuNear(phantom.volume, {125 * side, -15, z}, 6), 200) << side;
  }
}

TEST(Phantom, AirSurroundsTheBody) {
  const Phantom phantom =
      generatePhantom({.dims = kSmallDims, .seed = 1, .style = PhantomStyle::simple});
  const Volume& volume = phantom.volume;
  const glm::ivec3 last = volume.dims - 1;
  for (int k = 0; k < volume.dims.z; k += 10) {
    for (glm::ivec3 corner : {glm::ivec3(0, 0, k), glm::ivec3(last.x, 0, k), glm::ivec3(0, last.y, k),
                              glm::ivec3(last.x, last.y, k)}) {
      EXPECT_LT(huAt(volume, corner), -900) << k;
    }
  }
  // Between the knees, and in front of the shins.
  EXPECT_LT(huAt(volume, voxelAtPoint(volume, {0, 40, 500 - 1200})), -900);
  EXPECT_LT(huAt(volume, voxelAtPoint(volume, {90, -60, 300 - 1200})), -900);
  // Soft tissue inside: the middle of the left calf.
  const double calf = huAt(volume, voxelAtPoint(volume, {95, 70, 330 - 1200}));
  EXPECT_GT(calf, 0);
  EXPECT_LT(calf, 120);
}

TEST(Phantom, ReportsProgressUpToOne) {
  std::vector<double> reports;
  generatePhantom({.dims = {32, 32, 100}, .seed = 1, .style = PhantomStyle::simple},
                  [&](double f) { reports.push_back(f); });
  ASSERT_GE(reports.size(), 2u);
  EXPECT_TRUE(std::is_sorted(reports.begin(), reports.end()));
  EXPECT_GT(reports.front(), 0.0);
  EXPECT_DOUBLE_EQ(reports.back(), 1.0);
}

TEST(Phantom, RejectsNonPositiveDims) {
  EXPECT_THROW(generatePhantom({.dims = {0, 10, 10}, .seed = 1, .style = PhantomStyle::simple}),
               std::invalid_argument);
}

}  // namespace
}  // namespace angio
