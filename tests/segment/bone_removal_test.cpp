// Automatic bone and table removal: detection rates on the phantom against its ground truth, and
// synthetic cases: a contrast tube touching bone, a calcified plaque ring, a vessel through bone
// protected by its centerline, user labels kept, cancel, progress.
#include "segment/bone_removal.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "core/labels.h"
#include "phantom/phantom.h"
#include "tests/segment/detection_rates.h"

namespace angio {
namespace {

using test_support::DetectionRates;

// A phantom with its ground truth in the label bits, and the same voxels without labels (the
// segmentation's input).
struct PhantomCase {
  Phantom truth;
  Volume input;
};

PhantomCase phantomCase(glm::ivec3 dims) {
  PhantomOptions options;
  options.style = PhantomStyle::simple;
  options.dims = dims;
  options.groundTruthLabels = true;
  PhantomCase c{generatePhantom(options), {}};
  c.input = c.truth.volume;
  for (Voxel& v : c.input.voxels) v = Voxel(densityOf(v));
  return c;
}

// The full-size phantom, where the targets are set: at 128 x 128 x 300 (3.2 mm voxels) or
// 256 x 256 x 600 the phantom's 1.5-2 mm cortices (vertebrae, pelvis, epiphyses) blur below the
// lumen's density, so no density threshold can tell them from contrast (about a fifth, a third of
// the bone is found there). ANGIORAY_SEGMENT_PHANTOM=IxJxK measures another size (numbers printed).
glm::ivec3 phantomDims() {
  glm::ivec3 dims{512, 512, 1200};
  if (const char* size = std::getenv("ANGIORAY_SEGMENT_PHANTOM"))
    std::sscanf(size, "%dx%dx%d", &dims.x, &dims.y, &dims.z);
  return dims;
}

TEST(BoneRemoval, FindsThePhantomsBoneAndTableButNotItsLumen) {
  // Targets: bone >= 97 %, table >= 99 %, lumen as bone <= 0.5 %; other tissue as bone <= 1 % (the
  // bone's partial-volume rim is labelled on purpose, so hiding bone leaves no halo).
  const glm::ivec3 dims = phantomDims();
  const PhantomCase c = phantomCase(dims);
  const auto start = std::chrono::steady_clock::now();
  const LabelResult result = removeBoneAndTable(c.input, nullptr);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_FALSE(result.cancelled);
  const DetectionRates rates = test_support::detectionRates(c.truth, result.labels);
  std::printf(
      "phantom %dx%dx%d in %.2f s: bone found %.3f%% of %zu, table found %.3f%% of %zu, "
      "lumen as bone %.3f%% of %zu, other as bone %.3f%%\n",
      dims.x, dims.y, dims.z, seconds, 100 * rates.boneFoundFraction(), rates.bone,
      100 * rates.tableFoundFraction(), rates.table, 100 * rates.lumenAsBoneFraction(), rates.lumen,
      100 * rates.otherAsBoneFraction());
  EXPECT_GE(rates.boneFoundFraction(), 0.97);
  EXPECT_GE(rates.tableFoundFraction(), 0.99);
  EXPECT_LE(rates.lumenAsBoneFraction(), 0.005);
  EXPECT_LE(rates.otherAsBoneFraction(), 0.01);
  EXPECT_EQ(
      result.voxelsPerLabel[kBoneLabel] + result.voxelsPerLabel[kTableLabel] + result.voxelsPerLabel[0],
      c.input.voxelCount());
}

// ---- Synthetic scenes: 0.8 mm voxels (the coarse grid is used), soft tissue at 50 HU.

constexpr double kSpacingMm = 0.8;
constexpr double kMuscleHu = 50;
constexpr double kLumenHu = 400;

glm::dvec3 mmOf(glm::ivec3 index) { return glm::dvec3(index) * kSpacingMm; }

template <class HuAt>
Volume scene(glm::ivec3 dims, HuAt&& huAt) {
  Volume volume = makeVolume(dims, glm::dvec3(kSpacingMm));
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i)
        volume.voxels[volume.indexOf(i, j, k)] = encodeVoxel(huAt(mmOf({i, j, k})));
  return volume;
}

// A bone block (2 mm cortex at 1000 HU around cancellous bone at 200 HU) spanning x in [10, 34] mm.
bool inBlock(glm::dvec3 p) { return p.x >= 10 && p.x <= 34 && p.y >= 10 && p.y <= 38; }
double blockHu(glm::dvec3 p) {
  const bool core = p.x >= 12 && p.x <= 32 && p.y >= 12 && p.y <= 36;
  return core ? 200 : 1000;
}

// The distance (mm) from p to a tube along z through (x, y).
double tubeDistance(glm::dvec3 p, glm::dvec2 axis) { return glm::length(glm::dvec2(p) - axis); }

struct Tally {
  std::size_t voxels = 0, bone = 0;
  double boneFraction() const { return double(bone) / double(voxels); }
};

template <class Where>
Tally tally(const Volume& volume, const std::vector<std::uint8_t>& labels, Where&& where) {
  Tally t;
  for (int k = 0; k < volume.dims.z; ++k)
    for (int j = 0; j < volume.dims.y; ++j)
      for (int i = 0; i < volume.dims.x; ++i) {
        if (!where(mmOf({i, j, k}))) continue;
        ++t.voxels;
        t.bone += labels[volume.indexOf(i, j, k)] == kBoneLabel;
      }
  return t;
}

constexpr glm::ivec3 kSceneDims{64, 64, 60};
constexpr double kTubeRadiusMm = 4;

TEST(BoneRemoval, ContrastTubeTouchingBoneIsNotBone) {
  const glm::dvec2 axis{34 + kTubeRadiusMm, 24};  // the tube's wall touches the block's side
  const Volume volume = scene(kSceneDims, [&](glm::dvec3 p) {
    if (tubeDistance(p, axis) <= kTubeRadiusMm) return kLumenHu;
    return inBlock(p) ? blockHu(p) : kMuscleHu;
  });
  const LabelResult result = removeBoneAndTable(volume, nullptr);
  const Tally lumen = tally(volume, result.labels,
                            [&](glm::dvec3 p) { return tubeDistance(p, axis) <= kTubeRadiusMm - 0.5; });
  const Tally block = tally(volume, result.labels, [](glm::dvec3 p) { return inBlock(p); });
  EXPECT_EQ(lumen.bone, 0u) << "of " << lumen.voxels;
  EXPECT_GE(block.boneFraction(), 0.97);
}

TEST(BoneRemoval, CalcifiedPlaqueRingOnAVesselIsNotBone) {
  const glm::dvec2 axis{26, 26};
  const auto inRing = [&](glm::dvec3 p) {
    const double d = tubeDistance(p, axis);
    return d > kTubeRadiusMm && d <= kTubeRadiusMm + 1.5 && p.z >= 20 && p.z <= 30;
  };
  const Volume volume = scene(kSceneDims, [&](glm::dvec3 p) {
    if (tubeDistance(p, axis) <= kTubeRadiusMm) return kLumenHu;
    return inRing(p) ? 1200.0 : kMuscleHu;
  });
  const LabelResult result = removeBoneAndTable(volume, nullptr);
  EXPECT_EQ(result.voxelsPerLabel[kBoneLabel], 0u);
}

// A vessel running through a bone (as vertebral arteries do through the transverse foramina): its
// lumen is a hole in the bone, so only its centerline can keep it out of the bone label.
TEST(BoneRemoval, CenterlinesProtectTheirLumen) {
  const glm::dvec2 axis{22, 24};
  const Volume volume = scene(kSceneDims, [&](glm::dvec3 p) {
    if (tubeDistance(p, axis) <= kTubeRadiusMm) return kLumenHu;
    if (tubeDistance(p, axis) <= kTubeRadiusMm + 1.5) return 1000.0;  // the foramen's cortex
    return inBlock(p) ? blockHu(p) : kMuscleHu;
  });
  Centerlines centerlines;
  centerlines.frame = CenterlineFrame::volume;
  centerlines.paths.push_back(
      {"through bone", {{{axis, -5.0}, kTubeRadiusMm}, {{axis, 60.0}, kTubeRadiusMm}}});
  const BoneRemovalOptions options;
  const auto protectedZone = [&](glm::dvec3 p) {
    return tubeDistance(p, axis) <= kTubeRadiusMm + options.protectMarginMm;
  };
  const LabelResult without = removeBoneAndTable(volume, nullptr, options);
  EXPECT_GT(tally(volume, without.labels, protectedZone).boneFraction(), 0.5) << "the hole is filled";
  const LabelResult with = removeBoneAndTable(volume, &centerlines, options);
  EXPECT_EQ(tally(volume, with.labels, protectedZone).bone, 0u);
  EXPECT_GE(tally(volume, with.labels, [&](glm::dvec3 p) { return inBlock(p) && !protectedZone(p); })
                .boneFraction(),
            0.95);
}

Volume blockScene() {
  return scene(kSceneDims, [](glm::dvec3 p) { return inBlock(p) ? blockHu(p) : kMuscleHu; });
}

TEST(BoneRemoval, KeepsUserLabelsAndRecomputesItsOwn) {
  Volume volume = blockScene();
  // User label 7 over a corner of the block and some muscle; a stale bone label in the muscle.
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i) {
        Voxel& v = volume.voxels[volume.indexOf(i, j, k)];
        v = Voxel(densityOf(v) | (7 << 12));
      }
  Voxel& stale = volume.voxels[volume.indexOf(60, 60, 50)];
  stale = Voxel(densityOf(stale) | (kBoneLabel << 12));
  const LabelResult result = removeBoneAndTable(volume, nullptr);
  EXPECT_EQ(result.voxelsPerLabel[7], 20u * 20 * 10);
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i) ASSERT_EQ(result.labels[volume.indexOf(i, j, k)], 7);
  EXPECT_EQ(result.labels[volume.indexOf(60, 60, 50)], 0);
  EXPECT_GT(result.voxelsPerLabel[kBoneLabel], 0u);
}

TEST(BoneRemoval, TableOnlyLeavesBoneLabelsAlone) {
  Volume volume = blockScene();
  Voxel& old = volume.voxels[volume.indexOf(60, 60, 50)];
  old = Voxel(densityOf(old) | (kBoneLabel << 12));
  BoneRemovalOptions options;
  options.bone = false;
  const LabelResult result = removeBoneAndTable(volume, nullptr, options);
  EXPECT_EQ(result.voxelsPerLabel[kBoneLabel], 1u);
  EXPECT_EQ(result.labels[volume.indexOf(60, 60, 50)], kBoneLabel);
}

TEST(BoneRemoval, ReportsProgressUpToOne) {
  std::vector<double> reports;
  removeBoneAndTable(blockScene(), nullptr, {}, {.progress = [&](double f) { reports.push_back(f); }});
  ASSERT_GE(reports.size(), 5u);
  EXPECT_TRUE(std::is_sorted(reports.begin(), reports.end()));
  EXPECT_DOUBLE_EQ(reports.back(), 1.0);
}

TEST(BoneRemoval, CancelReturnsPromptlyWithNoLabels) {
  // Promptly, measured in work rather than time: once cancelled a fifth of the way, the run stops
  // within the step it is in (no progress beyond half) and returns no labels.
  const PhantomCase c = phantomCase({128, 128, 300});
  std::atomic<bool> cancel{false};
  double furthest = 0;
  const auto cancelAtAFifth = [&](double fraction) {
    if (cancel) furthest = std::max(furthest, fraction);
    if (fraction >= 0.2) cancel = true;
  };
  const LabelResult result = removeBoneAndTable(c.input, nullptr, {}, {cancelAtAFifth, &cancel});
  EXPECT_TRUE(result.cancelled);
  EXPECT_TRUE(result.labels.empty());
  EXPECT_LT(furthest, 0.5);
  // Cancelled before it starts: nothing happens at all.
  const std::atomic<bool> already{true};
  EXPECT_TRUE(removeBoneAndTable(c.input, nullptr, {}, {{}, &already}).cancelled);
}

TEST(BoneRemoval, ApplyLabelsWritesTheLabelBitsOnly) {
  Volume volume = blockScene();
  const std::vector<Voxel> before = volume.voxels;
  std::vector<std::uint8_t> labels(volume.voxelCount(), 0);
  labels[5] = kTableLabel;
  applyLabels(volume, labels);
  EXPECT_EQ(labelOf(volume.voxels[5]), kTableLabel);
  EXPECT_EQ(densityOf(volume.voxels[5]), densityOf(before[5]));
  EXPECT_EQ(volume.voxels[6], before[6]);
}

TEST(BoneRemoval, WarnsWhenTheVolumeHoldsNoAirAsUncalibratedDataDoes) {
  Volume volume = makeVolume({20, 20, 20}, {1, 1, 1}, encodeVoxel(300));
  EXPECT_NE(calibrationWarning(volume), "");  // e.g. an MR angiogram: nothing near -1000 HU
  for (int n = 0; n < 400; ++n) volume.voxels[n] = encodeVoxel(-1000);  // 5 % air
  EXPECT_EQ(calibrationWarning(volume), "");
}

}  // namespace
}  // namespace angio
