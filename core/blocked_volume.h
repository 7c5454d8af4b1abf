#pragma once
// Blocked volume (thesis sec. 4.2.1 "Memory Structure", fig. 4.1, and sec. 4.3.1): the volume cut
// into 32^3 blocks, each stored as 35^3 voxels with an overlap copied from its neighbours (one
// voxel below, two above along each axis), so that a sample attributed to a block reads that
// block's storage only, its gradients included. Blocks that hold background only (air, label 0)
// are not stored; they all point at one shared dummy block. Per-block min/max density lets a TF
// change re-classify every block without reading a voxel again (thesis sec. 4.2.2, the integrated
// opacity table).
//
// The stored window of block b along an axis of n voxels is the global voxels 32b - 1 .. 32b + 33,
// each clamped to [0, n - 1]: at the volume's faces (and past the end of a partial last block)
// the window holds edge-replicated voxels, i.e. exactly what core/volume_sampling.h's clamped reads
// return. Local coordinate l in [0, 35) is global 32b - 1 + l; the block's own voxels ("core")
// are l = 1 .. 32.
//
// What a block serves without leaving its storage (attribute samples to blocks this way):
//   - nearest, mean: samples whose nearest voxel floor(q + 0.5) lies in the core (the mean filter
//     and central differences read that voxel +-1);
//   - trilinear density and gradient: samples whose cell base (cellAt) lies in the core; the
//     central differences at the 8 corners read base - 1 .. base + 2, l = 0 .. 34 (the thesis's
//     one-voxel overlap would miss l = 34 for a base on the core's last layer, 1 cell in 32);
//   - central differences at any core voxel.
// Since the window replicates the faces, these reads need no clamping and no test for the
// volume's faces: the same offsets serve every cell (core/voxel_grid.h).
//
// The dummy block is lossy by design: its voxels are not the true air voxels (air is noisy, so no
// single value could stand for them). It is exact for rendering with any TF that is transparent
// below the background threshold (see blocksServe in core/fast_raycaster.h): every voxel a sample
// attributed to a background block reads is below the threshold, so is every interpolation of
// them, so the reference renderer composites nothing there either. The per-block min/max stay the
// true ones, so classifyBlocks stays honest, and tfNeedsBackgroundVoxels says when a TF makes
// background visible (then render from the flat Volume).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "core/transfer_function.h"
#include "core/volume.h"

namespace angio {

constexpr int kBlockSize = 32;         // voxels a block owns along each axis
constexpr int kBlockOverlapBelow = 1;  // voxels copied from the neighbour below, along each axis
constexpr int kBlockOverlapAbove = 2;  // and from the one above
constexpr int kStoredBlockSize = kBlockSize + kBlockOverlapBelow + kBlockOverlapAbove;  // 35
constexpr std::size_t kStoredBlockVoxels =
    std::size_t(kStoredBlockSize) * kStoredBlockSize * kStoredBlockSize;  // 42875
// Storage per block: one voxel more, so that every block starts on a 32-bit word (the sample
// batches, core/sample_batch.h, read voxels as aligned words) and a word read of a block's last
// voxel stays in the storage.
constexpr std::size_t kBlockSlotVoxels = kStoredBlockVoxels + 1;

// Every voxel of the shared dummy block: density 0 (-1024 HU), label 0.
constexpr Voxel kDummyVoxel = 0;

struct BlockingOptions {
  // A block is background iff every voxel of its stored window (overlap included) has a density
  // below densityOfHu(backgroundBelowHu) and label 0. Labelled voxels are never background: a
  // per-label TF may show them whatever their density. Default -900 HU: density d < 124.
  double backgroundBelowHu = -900;
};

struct BlockedVolume {
  static constexpr std::size_t kNoDummy = std::numeric_limits<std::size_t>::max();

  glm::ivec3 dims{0};         // voxels, as in the source Volume
  glm::dvec3 spacing{1.0};    // mm per voxel step, as in the source Volume
  glm::ivec3 blocks{0};       // blocks per axis: ceil(dims / 32)
  int backgroundDensity = 0;  // densities below this (with label 0) are background
  // All stored blocks back to back, kBlockSlotVoxels apart (kStoredBlockVoxels each, local i
  // fastest, then j, then k, and one spare). The dummy (if any block is background) is stored
  // once, first.
  std::vector<Voxel> storage;
  // Per block (index (bk * blocks.y + bj) * blocks.x + bi): where its voxels start in `storage`.
  // Offsets rather than pointers, so the struct can be moved and copied.
  std::vector<std::size_t> blockOffset;
  // Per block, the true min/max density over its stored window (overlap included), i.e. over
  // every voxel a sample attributed to the block can read; true values for background blocks too.
  std::vector<std::uint16_t> minDensity;
  std::vector<std::uint16_t> maxDensity;
  std::size_t dummyOffset = kNoDummy;
  int backgroundBlocks = 0;  // blocks that share the dummy

  int blockCount() const { return blocks.x * blocks.y * blocks.z; }
  int blockIndex(glm::ivec3 block) const { return (block.z * blocks.y + block.y) * blocks.x + block.x; }
  glm::ivec3 blockCoord(int block) const {
    return {block % blocks.x, block / blocks.x % blocks.y, block / (blocks.x * blocks.y)};
  }
  // Global voxel index of the block's local (0, 0, 0), the first overlap voxel (may be -1).
  static glm::ivec3 windowOrigin(glm::ivec3 block) { return block * kBlockSize - kBlockOverlapBelow; }
  static std::size_t localIndex(glm::ivec3 local) {
    return (std::size_t(local.z) * kStoredBlockSize + local.y) * kStoredBlockSize + local.x;
  }

  bool isBackground(int block) const { return blockOffset[block] == dummyOffset; }
  // The block's 35^3 voxels (the dummy's for a background block).
  const Voxel* blockVoxels(int block) const { return storage.data() + blockOffset[block]; }

  // Voxel (i, j, k), 0 <= index < dims, read from the block that owns it. The true voxel for a
  // stored block; kDummyVoxel for a background block (the true value is only known to be label 0
  // with a density in [minDensity, maxDensity] of that block, below backgroundDensity).
  Voxel voxel(int i, int j, int k) const {
    const glm::ivec3 v(i, j, k), block = v / kBlockSize;
    return blockVoxels(blockIndex(block))[localIndex(v - windowOrigin(block))];
  }
};

// Thesis sec. 4.2.1: blocks with overlap, min/max, one shared dummy. Parallel over blocks (oneTBB).
BlockedVolume buildBlockedVolume(const Volume& volume, BlockingOptions options = {});

// Thesis sec. 4.2.2 / 4.3.1: one byte per block, 1 iff TfTable::anyVisible(min, max) of the block,
// else 0 (skip). Reads only the per-block ranges; a background block is visible only for a TF that
// gives some background density an opacity (see tfNeedsBackgroundVoxels).
std::vector<std::uint8_t> classifyBlocks(const BlockedVolume& blocked, const TfTable& table);

// True iff some background block's true range is visible under the TF: its voxels are not stored,
// so this blocked volume cannot render the TF exactly and the flat Volume must be used instead.
bool tfNeedsBackgroundVoxels(const BlockedVolume& blocked, const TfTable& table);

// Heap bytes held by the blocked volume (storage, tables; allocated capacity) plus the struct.
std::size_t memoryBytes(const BlockedVolume& blocked);

// Numbers for a benchmark: one build, classification timed as the median of several runs.
struct BlockingReport {
  double buildMs = 0;      // buildBlockedVolume, wall clock
  double classifyMs = 0;   // classifyBlocks, wall clock, median
  double memoryMiB = 0;    // memoryBytes
  double rawMiB = 0;       // the flat volume's voxels, 2 bytes each
  double memoryRatio = 0;  // memoryBytes / raw bytes
  int blocks = 0;
  int backgroundBlocks = 0;  // blocks sharing the dummy
  int visibleBlocks = 0;     // for the TF
  bool tfNeedsBackgroundVoxels = false;
};
BlockingReport blockingReport(const Volume& volume, const TfTable& table, BlockingOptions options = {});

}  // namespace angio
