// Blocked volume (thesis sec. 4.2.1): every stored voxel, overlap included, against the flat
// volume's clamped voxel; per-block ranges against a brute-force scan; the shared dummy for
// background blocks; classification against a per-density scan of the TF table; memory.
// The expected values are computed here from the flat Volume, not through the blocked volume.
#include "core/blocked_volume.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include "phantom/phantom.h"
#include "core/volume_sampling.h"

namespace angio {
namespace {

// Sizes that are not multiples of 32 along some axis, single-voxel axes, exact multiples, and
// one wide enough (> 96 along i) to have blocks whose window needs no clamping along i.
const std::vector<glm::ivec3> kSizes = {{33, 70, 5}, {1, 1, 1}, {64, 32, 65}, {2, 40, 1}, {100, 33, 34}};

Volume randomVolume(glm::ivec3 dims, unsigned seed) {
  Volume volume = makeVolume(dims, {0.7, 0.8, 1.25});
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> voxel(0, 0xFFFF);  // any density, any label
  for (Voxel& v : volume.voxels) v = Voxel(voxel(rng));
  return volume;
}

// Air with CT-like noise: densities 0 .. 100 (-1024 .. -924 HU), label 0.
Volume noisyAir(glm::ivec3 dims, unsigned seed) {
  Volume volume = makeVolume(dims, {1.0, 1.0, 1.0});
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> density(0, 100);
  for (Voxel& v : volume.voxels) v = Voxel(density(rng));
  return volume;
}

Voxel clampedVoxel(const Volume& volume, glm::ivec3 index) {
  const glm::ivec3 c = glm::clamp(index, glm::ivec3(0), volume.dims - 1);
  return volume.at(c.x, c.y, c.z);
}

// The block's 35^3 window of the flat volume, written out from the definition in the header.
template <typename Visit>
void forEachWindowVoxel(glm::ivec3 block, Visit&& visit) {
  for (int lk = 0; lk < 35; ++lk)
    for (int lj = 0; lj < 35; ++lj)
      for (int li = 0; li < 35; ++li)
        visit(glm::ivec3(li, lj, lk), block * 32 - 1 + glm::ivec3(li, lj, lk));
}

struct BruteForceBlock {
  int minDensity = 4096, maxDensity = -1;
  bool anyLabel = false;
};

BruteForceBlock scanWindow(const Volume& volume, glm::ivec3 block) {
  BruteForceBlock r;
  forEachWindowVoxel(block, [&](glm::ivec3, glm::ivec3 global) {
    const Voxel v = clampedVoxel(volume, global);
    r.minDensity = std::min(r.minDensity, densityOf(v));
    r.maxDensity = std::max(r.maxDensity, densityOf(v));
    r.anyLabel = r.anyLabel || labelOf(v) != 0;
  });
  return r;
}

glm::ivec3 expectedBlocks(glm::ivec3 dims) { return (dims + 31) / 32; }

TEST(BlockedVolume, StoredWindowsEqualClampedFlatVoxels) {
  for (glm::ivec3 dims : kSizes) {
    const Volume volume = randomVolume(dims, 7);
    const BlockedVolume blocked = buildBlockedVolume(volume);
    ASSERT_EQ(blocked.blocks, expectedBlocks(dims));
    ASSERT_EQ(blocked.backgroundBlocks, 0);
    for (int block = 0; block < blocked.blockCount(); ++block) {
      const glm::ivec3 b = blocked.blockCoord(block);
      const Voxel* stored = blocked.blockVoxels(block);
      int mismatches = 0;
      forEachWindowVoxel(b, [&](glm::ivec3 local, glm::ivec3 global) {
        const std::size_t n = (std::size_t(local.z) * 35 + local.y) * 35 + local.x;
        mismatches += stored[n] != clampedVoxel(volume, global);
      });
      EXPECT_EQ(mismatches, 0) << "dims " << dims.x << "x" << dims.y << "x" << dims.z << " block " << b.x
                               << "," << b.y << "," << b.z;
    }
  }
}

TEST(BlockedVolume, BlockCoordinatesRoundTrip) {
  const BlockedVolume blocked = buildBlockedVolume(randomVolume({70, 33, 100}, 1));
  ASSERT_EQ(blocked.blocks, glm::ivec3(3, 2, 4));
  for (int block = 0; block < blocked.blockCount(); ++block)
    EXPECT_EQ(blocked.blockIndex(blocked.blockCoord(block)), block);
  EXPECT_EQ(blocked.blockIndex({1, 0, 0}), 1);
  EXPECT_EQ(blocked.blockIndex({0, 1, 0}), 3);
  EXPECT_EQ(blocked.blockIndex({0, 0, 1}), 6);
}

TEST(BlockedVolume, RangesEqualBruteForceScanOfWindow) {
  for (glm::ivec3 dims : kSizes) {
    const Volume volume = randomVolume(dims, 11);
    const BlockedVolume blocked = buildBlockedVolume(volume);
    for (int block = 0; block < blocked.blockCount(); ++block) {
      const BruteForceBlock expected = scanWindow(volume, blocked.blockCoord(block));
      EXPECT_EQ(blocked.minDensity[block], expected.minDensity);
      EXPECT_EQ(blocked.maxDensity[block], expected.maxDensity);
    }
  }
}

// 96x64x40 of noisy air (blocks 3x2x2) with a few planted voxels; the block windows are
// i: -1..32 | 31..64 | 63..96, j: -1..32 | 31..64, k: -1..32 | 31..64 (clamped).
struct PlantedAir {
  Volume volume = noisyAir({96, 64, 40}, 3);
  PlantedAir() {
    auto set = [&](int i, int j, int k, Voxel v) { volume.voxels[volume.indexOf(i, j, k)] = v; };
    set(32, 5, 5, encodeVoxel(300));         // core of (1,0,0), overlap of (0,0,0)
    set(80, 40, 35, encodeVoxel(-1000, 3));  // labelled air in (2,1,1)
    set(10, 40, 10, encodeVoxel(-900));      // exactly at the threshold: (0,1,0)
    set(80, 40, 10, encodeVoxel(-901));      // just below it: (2,1,0) stays background
  }
};

TEST(BlockedVolume, DetectsBackgroundBlocksAndOverlapVoxels) {
  const PlantedAir planted;
  const BlockedVolume blocked = buildBlockedVolume(planted.volume);
  const std::vector<glm::ivec3> notBackground = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 1, 1}};
  for (int block = 0; block < blocked.blockCount(); ++block) {
    const glm::ivec3 b = blocked.blockCoord(block);
    const bool expected =
        std::find(notBackground.begin(), notBackground.end(), b) == notBackground.end();
    EXPECT_EQ(blocked.isBackground(block), expected) << "block " << b.x << "," << b.y << "," << b.z;
    const BruteForceBlock scan = scanWindow(planted.volume, b);
    EXPECT_EQ(blocked.isBackground(block), !scan.anyLabel && scan.maxDensity < 124);
  }
  EXPECT_EQ(blocked.backgroundBlocks, 8);
}

TEST(BlockedVolume, BackgroundThresholdIsConfigurable) {
  const PlantedAir planted;
  EXPECT_EQ(buildBlockedVolume(planted.volume, {.backgroundBelowHu = -2000}).backgroundBlocks, 0);
  // At -800 HU the -900 HU voxel is background too; the 300 HU and the labelled voxel are not.
  const BlockedVolume blocked = buildBlockedVolume(planted.volume, {.backgroundBelowHu = -800});
  EXPECT_EQ(blocked.backgroundBlocks, 9);
  EXPECT_TRUE(blocked.isBackground(blocked.blockIndex({0, 1, 0})));
}

TEST(BlockedVolume, VoxelAccessorGivesTrueVoxelOrTheDocumentedDummy) {
  const PlantedAir planted;
  const Volume& volume = planted.volume;
  const BlockedVolume blocked = buildBlockedVolume(volume);
  for (int k = 0; k < volume.dims.z; ++k)
    for (int j = 0; j < volume.dims.y; ++j)
      for (int i = 0; i < volume.dims.x; ++i) {
        const bool background = blocked.isBackground(blocked.blockIndex(glm::ivec3(i, j, k) / 32));
        const Voxel expected = background ? kDummyVoxel : volume.at(i, j, k);
        ASSERT_EQ(blocked.voxel(i, j, k), expected) << i << "," << j << "," << k;
      }
  // Background blocks keep their true ranges, not the dummy's.
  for (int block = 0; block < blocked.blockCount(); ++block) {
    if (!blocked.isBackground(block)) continue;
    const BruteForceBlock scan = scanWindow(volume, blocked.blockCoord(block));
    EXPECT_EQ(blocked.minDensity[block], scan.minDensity);
    EXPECT_EQ(blocked.maxDensity[block], scan.maxDensity);
  }
}

TEST(BlockedVolume, AllBackgroundBlocksShareOneStoredDummy) {
  const PlantedAir planted;
  const BlockedVolume blocked = buildBlockedVolume(planted.volume);
  const Voxel* dummy = nullptr;
  for (int block = 0; block < blocked.blockCount(); ++block) {
    if (!blocked.isBackground(block)) continue;
    if (!dummy) dummy = blocked.blockVoxels(block);
    EXPECT_EQ(blocked.blockVoxels(block), dummy);
  }
  ASSERT_NE(dummy, nullptr);
  EXPECT_TRUE(std::all_of(dummy, dummy + kStoredBlockVoxels, [](Voxel v) { return v == kDummyVoxel; }));
  EXPECT_EQ(blocked.storage.size(), (4 + 1) * kBlockSlotVoxels);  // 4 stored + the dummy
}

TEST(BlockedVolume, SingleVoxelVolume) {
  Volume volume = makeVolume({1, 1, 1}, {1, 1, 1}, encodeVoxel(250, 2));
  const BlockedVolume blocked = buildBlockedVolume(volume);
  ASSERT_EQ(blocked.blockCount(), 1);
  EXPECT_FALSE(blocked.isBackground(0));
  EXPECT_EQ(blocked.voxel(0, 0, 0), volume.at(0, 0, 0));
  const Voxel* stored = blocked.blockVoxels(0);
  EXPECT_TRUE(std::all_of(stored, stored + kStoredBlockVoxels,
                          [&](Voxel v) { return v == volume.at(0, 0, 0); }));
  EXPECT_EQ(blocked.minDensity[0], densityOfHu(250));
  EXPECT_EQ(blocked.maxDensity[0], densityOfHu(250));

  const BlockedVolume air = buildBlockedVolume(makeVolume({1, 1, 1}, {1, 1, 1}, encodeVoxel(-1000)));
  EXPECT_TRUE(air.isBackground(0));
  EXPECT_EQ(air.storage.size(), kBlockSlotVoxels);
}

// Reads through the block's storage with local offsets only, as a block renderer would, must
// give volume_sampling.h's clamped results bit for bit: voxel gradients, the mean filter at the
// nearest voxel, and trilinear density and gradient at the cell base (including the volume's last
// cell).
struct BlockReader {
  const BlockedVolume& blocked;
  const Voxel* voxels = nullptr;
  glm::ivec3 origin{0};

  BlockReader(const BlockedVolume& b, glm::ivec3 ownedVoxel) : blocked(b) {
    const glm::ivec3 block = ownedVoxel / 32;
    voxels = blocked.blockVoxels(blocked.blockIndex(block));
    origin = BlockedVolume::windowOrigin(block);
  }
  float density(glm::ivec3 global) const {
    const glm::ivec3 local = global - origin;
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(local, glm::ivec3(0))) &&
                glm::all(glm::lessThan(local, glm::ivec3(35))));
    return float(densityOf(voxels[BlockedVolume::localIndex(local)]));
  }
  glm::vec3 gradient(glm::ivec3 v) const {
    glm::vec3 g;
    for (int axis = 0; axis < 3; ++axis) {
      glm::ivec3 lo = v, hi = v;
      --lo[axis];
      ++hi[axis];
      g[axis] = centralDifference(density(lo), density(hi), blocked.spacing[axis]);
    }
    return g;
  }
  float mean(glm::ivec3 v) const {
    float sum = density(v);
    for (int axis = 0; axis < 3; ++axis) {
      glm::ivec3 lo = v, hi = v;
      --lo[axis];
      ++hi[axis];
      sum += density(lo) + density(hi);
    }
    return sum / 7.f;
  }
  float trilinearDensity(const Cell& cell) const {
    return trilinear(
        cell, [&](int dx, int dy, int dz) { return density(cell.base + glm::ivec3(dx, dy, dz)); });
  }
};

TEST(BlockedVolume, BlockLocalReadsEqualClampedSampling) {
  for (glm::ivec3 dims : kSizes) {
    const Volume volume = randomVolume(dims, 5);
    const BlockedVolume blocked = buildBlockedVolume(volume);
    std::mt19937 rng(9);
    // The first and last cell, and cells based on a core's last layer (l = 32) where they exist.
    std::vector<glm::dvec3> points = {
        glm::dvec3(0.0), glm::dvec3(volume.dims - 1),
        glm::min(glm::dvec3(31.5, 63.25, 31.75), glm::dvec3(volume.dims - 1))};
    for (int n = 0; n < 2000; ++n) {
      glm::dvec3 q;
      for (int axis = 0; axis < 3; ++axis)
        q[axis] = std::uniform_real_distribution<double>(0, dims[axis] - 1)(rng);
      points.push_back(q);
    }
    for (glm::dvec3 q : points) {
      const glm::ivec3 v = nearestVoxel(volume, q);
      const BlockReader atVoxel(blocked, v);
      EXPECT_EQ(atVoxel.gradient(v), voxelGradient(volume, v));
      EXPECT_EQ(atVoxel.mean(v), meanDensity(volume, v));
      const Cell cell = cellAt(volume, q);
      const BlockReader atCell(blocked, cell.base);
      EXPECT_EQ(atCell.trilinearDensity(cell), trilinearDensity(volume, cell));
      // The corners' central differences, which trilinearGradient interpolates, read base - 1 ..
      // base + 2: two past the core for a base on its last layer. (Compared before the
      // interpolation, whose fused multiply-adds the compiler may contract with the differences
      // differently in different places.)
      for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 v = cell.base + glm::ivec3(corner & 1, corner >> 1 & 1, corner >> 2);
        EXPECT_EQ(atCell.gradient(v), voxelGradient(volume, clampIndex(volume, v)));
      }
    }
  }
}

TfTable tableOf(std::vector<ControlPoint> points) {
  TransferFunction tf;
  tf.points = std::move(points);
  return buildTable(tf);
}

// The shape of presets/cta-vessels.json: lumen 220 .. 650 HU visible, the rest transparent.
TfTable ctaLikeTable() {
  return tableOf({{-1024, {0, 0, 0}, 0.0},
                  {140, {0.55f, 0.06f, 0.03f}, 0.0},
                  {220, {0.8f, 0.18f, 0.1f}, 0.35},
                  {400, {0.95f, 0.4f, 0.28f}, 0.7},
                  {650, {1, 0.72f, 0.6f}, 0.8},
                  {800, {1, 0.9f, 0.85f}, 0.0},
                  {3071, {1, 1, 1}, 0.0}});
}

std::vector<TfTable> testTables() {
  return {ctaLikeTable(), tableOf({}),                                 // all transparent
          tableOf({{-1024, {1, 1, 1}, 0.2}, {-950, {1, 1, 1}, 0.0}}),  // air only
          tableOf({{-1000, {1, 1, 1}, 0.0},
                   {-899, {1, 1, 1}, 0.0},
                   {-898, {1, 1, 1}, 1.0},
                   {-897, {1, 1, 1}, 0.0}}),                         // one density
          tableOf({{0, {1, 1, 1}, 0.0}, {3071, {1, 1, 1}, 1e-6}})};  // tiny opacities
}

// Brute force: does the block's density range hold a density whose table opacity is > 0?
bool rangeVisible(const TfTable& table, const BruteForceBlock& scan) {
  for (int d = scan.minDensity; d <= scan.maxDensity; ++d)
    if (table.rgba[d].a > 0.f) return true;
  return false;
}

bool anyVoxelVisible(const Volume& volume, const TfTable& table, glm::ivec3 block) {
  bool visible = false;
  forEachWindowVoxel(block, [&](glm::ivec3, glm::ivec3 global) {
    visible = visible || table.rgba[densityOf(clampedVoxel(volume, global))].a > 0.f;
  });
  return visible;
}

TEST(BlockedVolume, ClassificationMatchesBruteForce) {
  const PlantedAir planted;
  std::vector<Volume> volumes;
  volumes.push_back(planted.volume);
  volumes.push_back(randomVolume({33, 70, 5}, 2));
  for (const Volume& volume : volumes) {
    const BlockedVolume blocked = buildBlockedVolume(volume);
    for (const TfTable& table : testTables()) {
      const std::vector<std::uint8_t> visible = classifyBlocks(blocked, table);
      ASSERT_EQ(int(visible.size()), blocked.blockCount());
      for (int block = 0; block < blocked.blockCount(); ++block) {
        const glm::ivec3 b = blocked.blockCoord(block);
        EXPECT_EQ(visible[block] != 0, rangeVisible(table, scanWindow(volume, b)));
        if (anyVoxelVisible(volume, table, b)) {
          EXPECT_TRUE(visible[block]);  // never misses a visible voxel
        }
      }
    }
  }
}

TEST(BlockedVolume, PlantedAirClassification) {
  const PlantedAir planted;
  const BlockedVolume blocked = buildBlockedVolume(planted.volume);
  const std::vector<std::uint8_t> visible = classifyBlocks(blocked, ctaLikeTable());
  // Only the 300 HU voxel is visible under the CTA TF: it is in (1,0,0) and in (0,0,0)'s overlap.
  for (int block = 0; block < blocked.blockCount(); ++block) {
    const glm::ivec3 b = blocked.blockCoord(block);
    EXPECT_EQ(visible[block] != 0, b == glm::ivec3(0, 0, 0) || b == glm::ivec3(1, 0, 0));
  }
}

TEST(BlockedVolume, SaysWhenATfNeedsTheUnstoredBackground) {
  const BlockedVolume blocked = buildBlockedVolume(PlantedAir().volume);
  const std::vector<TfTable> tables = testTables();
  EXPECT_FALSE(tfNeedsBackgroundVoxels(blocked, tables[0]));  // CTA: transparent below -900 HU
  EXPECT_FALSE(tfNeedsBackgroundVoxels(blocked, tables[1]));
  EXPECT_TRUE(tfNeedsBackgroundVoxels(blocked, tables[2]));   // shows air
  EXPECT_FALSE(tfNeedsBackgroundVoxels(blocked, tables[3]));  // -898 HU is above the threshold
}

std::size_t tableBytes(int blocks) {
  return std::size_t(blocks) * (sizeof(std::size_t) + 2 * sizeof(std::uint16_t));
}
constexpr std::size_t kBlockBytes = (35 * 35 * 35 + 1) * sizeof(Voxel);  // one spare voxel

TEST(BlockedVolume, CountsMemory) {
  // No background: every block stored, no dummy.
  const BlockedVolume dense = buildBlockedVolume(randomVolume({64, 32, 65}, 4));
  EXPECT_EQ(dense.dummyOffset, BlockedVolume::kNoDummy);
  EXPECT_EQ(memoryBytes(dense), sizeof(BlockedVolume) + 6 * kBlockBytes + tableBytes(6));
  // Only background: 4x4x4 blocks, one dummy stored.
  const BlockedVolume air = buildBlockedVolume(noisyAir({100, 100, 100}, 8));
  EXPECT_EQ(air.backgroundBlocks, 64);
  EXPECT_EQ(memoryBytes(air), sizeof(BlockedVolume) + 1 * kBlockBytes + tableBytes(64));
  // Mixed: 4 stored blocks + the dummy.
  const BlockedVolume mixed = buildBlockedVolume(PlantedAir().volume);
  EXPECT_EQ(memoryBytes(mixed), sizeof(BlockedVolume) + 5 * kBlockBytes + tableBytes(12));
}

TEST(BlockedVolume, ReportAddsUp) {
  const PlantedAir planted;
  const BlockingReport report = blockingReport(planted.volume, ctaLikeTable());
  EXPECT_EQ(report.blocks, 12);
  EXPECT_EQ(report.backgroundBlocks, 8);
  EXPECT_EQ(report.visibleBlocks, 2);
  EXPECT_FALSE(report.tfNeedsBackgroundVoxels);
  const double raw = 96.0 * 64 * 40 * 2;
  EXPECT_DOUBLE_EQ(report.rawMiB, raw / (1 << 20));
  EXPECT_DOUBLE_EQ(report.memoryRatio,
                   double(sizeof(BlockedVolume) + 5 * kBlockBytes + tableBytes(12)) / raw);
  EXPECT_GE(report.buildMs, 0.0);
  EXPECT_GE(report.classifyMs, 0.0);
}

// Timing and memory on the benchmark phantom; not a unit test (it times, and takes a while).
// Run: core_tests --gtest_also_run_disabled_tests --gtest_filter='*PhantomBlockingReport*'
TEST(BlockedVolume, DISABLED_PhantomBlockingReport) {
  const Volume volume = generatePhantom({.style = PhantomStyle::simple}).volume;
  std::vector<double> buildMs, classifyMs;
  BlockingReport report;
  for (int run = 0; run < 5; ++run) {
    report = blockingReport(volume, ctaLikeTable());
    buildMs.push_back(report.buildMs);
    classifyMs.push_back(report.classifyMs);
    std::printf("run %d: build %.1f ms, classify %.4f ms\n", run, report.buildMs, report.classifyMs);
  }
  std::sort(buildMs.begin(), buildMs.end());
  std::sort(classifyMs.begin(), classifyMs.end());
  std::printf("%dx%dx%d: %d blocks, %d background (dummy), %d visible (CTA-like TF)\n", volume.dims.x,
              volume.dims.y, volume.dims.z, report.blocks, report.backgroundBlocks,
              report.visibleBlocks);
  std::printf(
      "median build %.1f ms, median classify %.4f ms, memory %.1f MiB, raw %.1f MiB, ratio %.3f\n",
      buildMs[2], classifyMs[2], report.memoryMiB, report.rawMiB, report.memoryRatio);
  EXPECT_LE(report.memoryRatio, 1.3);
  EXPECT_FALSE(report.tfNeedsBackgroundVoxels);
}

}  // namespace
}  // namespace angio
