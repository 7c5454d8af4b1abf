#include "core/blocked_volume.h"

#include <algorithm>
#include <array>
#include <chrono>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

namespace angio {

namespace {

using WindowIndices = std::array<int, kStoredBlockSize>;

// The global voxel each local coordinate of block `block` (along an axis of n voxels) reads:
// 32 b - 1 + l clamped to [0, n - 1], the edge replication of volume_sampling.h's clamped reads.
WindowIndices windowIndices(int block, int n) {
  WindowIndices indices;
  const int first = block * kBlockSize - kBlockOverlapBelow;
  for (int l = 0; l < kStoredBlockSize; ++l) indices[l] = std::clamp(first + l, 0, n - 1);
  return indices;
}

// Fills `out` (kStoredBlockVoxels) with the block's clamped window of the flat volume. Rows that
// need no clamping along i (all but the blocks on the i faces) are one contiguous copy.
void copyWindow(const Volume& volume, glm::ivec3 block, Voxel* out) {
  const WindowIndices is = windowIndices(block.x, volume.dims.x);
  const WindowIndices js = windowIndices(block.y, volume.dims.y);
  const WindowIndices ks = windowIndices(block.z, volume.dims.z);
  const bool rowContiguous = is.back() - is.front() == kStoredBlockSize - 1;
  for (int lk = 0; lk < kStoredBlockSize; ++lk) {
    for (int lj = 0; lj < kStoredBlockSize; ++lj) {
      const Voxel* row = volume.voxels.data() + volume.indexOf(0, js[lj], ks[lk]);
      if (rowContiguous) {
        std::copy_n(row + is.front(), kStoredBlockSize, out);
      } else {
        for (int li = 0; li < kStoredBlockSize; ++li) out[li] = row[is[li]];
      }
      out += kStoredBlockSize;
    }
  }
}

struct WindowSummary {
  std::uint16_t minDensity = 0xFFFF;
  std::uint16_t maxDensity = 0;
  bool anyLabel = false;
};

WindowSummary summarise(const Voxel* voxels) {
  std::uint16_t lo = 0xFFFF, hi = 0, labels = 0;
  for (std::size_t n = 0; n < kStoredBlockVoxels; ++n) {  // branch-free, so it vectorises
    const std::uint16_t d = std::uint16_t(voxels[n] & 0x0FFF);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
    labels |= voxels[n];
  }
  return {lo, hi, (labels >> 12) != 0};
}

bool isBackgroundWindow(const WindowSummary& s, int backgroundDensity) {
  return !s.anyLabel && s.maxDensity < backgroundDensity;
}

BlockedVolume emptyBlockedVolume(const Volume& volume, BlockingOptions options) {
  BlockedVolume blocked;
  blocked.dims = volume.dims;
  blocked.spacing = volume.spacing;
  blocked.blocks = (volume.dims + kBlockSize - 1) / kBlockSize;
  blocked.backgroundDensity = densityOfHu(options.backgroundBelowHu);
  const std::size_t count = blocked.blockCount();
  blocked.minDensity.resize(count);
  blocked.maxDensity.resize(count);
  blocked.blockOffset.resize(count);
  return blocked;
}

// Pass 1: min/max and background of every block's window, copied to a per-thread scratch block
// so the ranges are taken over exactly the voxels that will be stored.
std::vector<std::uint8_t> summariseBlocks(const Volume& volume, BlockedVolume& blocked) {
  std::vector<std::uint8_t> background(blocked.blockCount());
  tbb::enumerable_thread_specific<std::vector<Voxel>> scratches(kStoredBlockVoxels);
  tbb::parallel_for(0, blocked.blockCount(), [&](int block) {
    std::vector<Voxel>& scratch = scratches.local();
    copyWindow(volume, blocked.blockCoord(block), scratch.data());
    const WindowSummary s = summarise(scratch.data());
    blocked.minDensity[block] = s.minDensity;
    blocked.maxDensity[block] = s.maxDensity;
    background[block] = isBackgroundWindow(s, blocked.backgroundDensity);
  });
  return background;
}

// Pass 2: the dummy first (if needed), then the stored blocks in block order.
void assignOffsets(const std::vector<std::uint8_t>& background, BlockedVolume& blocked) {
  const int backgroundBlocks = int(std::count(background.begin(), background.end(), 1));
  blocked.backgroundBlocks = backgroundBlocks;
  std::size_t next = 0;
  if (backgroundBlocks > 0) {
    blocked.dummyOffset = 0;
    next = kBlockSlotVoxels;
  }
  for (int block = 0; block < blocked.blockCount(); ++block) {
    if (background[block]) {
      blocked.blockOffset[block] = blocked.dummyOffset;
    } else {
      blocked.blockOffset[block] = next;
      next += kBlockSlotVoxels;
    }
  }
  blocked.storage.resize(next);
}

// Pass 3: copy every stored block's window into its slot (the dummy keeps kDummyVoxel, the
// zero the storage was filled with).
void copyStoredBlocks(const Volume& volume, BlockedVolume& blocked) {
  static_assert(kDummyVoxel == 0, "storage is zero-filled, which is the dummy's value");
  tbb::parallel_for(0, blocked.blockCount(), [&](int block) {
    if (blocked.isBackground(block)) return;
    copyWindow(volume, blocked.blockCoord(block), blocked.storage.data() + blocked.blockOffset[block]);
  });
}

template <typename Fn>
double wallMs(Fn&& fn) {
  const auto start = std::chrono::steady_clock::now();
  fn();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

BlockedVolume buildBlockedVolume(const Volume& volume, BlockingOptions options) {
  BlockedVolume blocked = emptyBlockedVolume(volume, options);
  const std::vector<std::uint8_t> background = summariseBlocks(volume, blocked);
  assignOffsets(background, blocked);
  copyStoredBlocks(volume, blocked);
  return blocked;
}

std::vector<std::uint8_t> classifyBlocks(const BlockedVolume& blocked, const TfTable& table) {
  std::vector<std::uint8_t> visible(blocked.blockCount());
  for (int block = 0; block < blocked.blockCount(); ++block)
    visible[block] = table.anyVisible(blocked.minDensity[block], blocked.maxDensity[block]);
  return visible;
}

bool tfNeedsBackgroundVoxels(const BlockedVolume& blocked, const TfTable& table) {
  for (int block = 0; block < blocked.blockCount(); ++block)
    if (blocked.isBackground(block) &&
        table.anyVisible(blocked.minDensity[block], blocked.maxDensity[block]))
      return true;
  return false;
}

std::size_t memoryBytes(const BlockedVolume& blocked) {
  return sizeof(BlockedVolume) + blocked.storage.capacity() * sizeof(Voxel) +
         blocked.blockOffset.capacity() * sizeof(std::size_t) +
         (blocked.minDensity.capacity() + blocked.maxDensity.capacity()) * sizeof(std::uint16_t);
}

BlockingReport blockingReport(const Volume& volume, const TfTable& table, BlockingOptions options) {
  BlockingReport report;
  BlockedVolume blocked;
  report.buildMs = wallMs([&] { blocked = buildBlockedVolume(volume, options); });
  // Classification takes microseconds, so one run is timer noise: median of several.
  constexpr int kClassifyRuns = 9;
  std::array<double, kClassifyRuns> classifyMs;
  std::vector<std::uint8_t> visible;
  for (double& ms : classifyMs) ms = wallMs([&] { visible = classifyBlocks(blocked, table); });
  std::nth_element(classifyMs.begin(), classifyMs.begin() + kClassifyRuns / 2, classifyMs.end());
  report.classifyMs = classifyMs[kClassifyRuns / 2];
  const double rawBytes = double(volume.voxelCount()) * sizeof(Voxel);
  report.memoryMiB = double(memoryBytes(blocked)) / (1 << 20);
  report.rawMiB = rawBytes / (1 << 20);
  report.memoryRatio = double(memoryBytes(blocked)) / rawBytes;
  report.blocks = blocked.blockCount();
  report.backgroundBlocks = blocked.backgroundBlocks;
  report.visibleBlocks = int(std::count(visible.begin(), visible.end(), 1));
  report.tfNeedsBackgroundVoxels = tfNeedsBackgroundVoxels(blocked, table);
  return report;
}

}  // namespace angio
