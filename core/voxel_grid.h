#pragma once
// Where the fast raycaster reads its voxels: the flat Volume, or the blocked volume
// (core/blocked_volume.h, thesis sec. 4.2.1), which then makes the flat voxels unnecessary while
// rendering. Both give the same densities for the same sample, bit for bit, wherever blocksServe
// allows the blocks: each read takes a voxel and the neighbours a filter needs as a pointer and
// strides, and the filters (core/volume_sampling.h) compute from them the same way.
//
// A sample reads the block that owns its voxel (nearest, mean) or its cell base (trilinear); the
// block's window holds every neighbour the filters read, replicated at the volume's faces, so the
// blocked grid never needs the clamped path. The flat grid does at the faces, and there reads the
// Volume's voxels through volume_sampling.h's clamped functions.
#include <cstddef>
#include <limits>
#include <stdexcept>

#include <glm/glm.hpp>

#include "core/blocked_volume.h"
#include "core/volume.h"
#include "core/volume_sampling.h"

namespace angio {

class VoxelGrid {
 public:
  // The flat volume's voxels.
  explicit VoxelGrid(const Volume& volume)
      : volume_(volume), steps_(cornerSteps(volume)), strides_(voxelStrides(volume)) {}
  // The blocks' voxels; `geometry` gives dims and spacing (its voxels are not read and may be
  // empty). Throws std::logic_error if the two differ in size.
  VoxelGrid(const Volume& geometry, const BlockedVolume& blocked)
      : volume_(geometry), blocked_(&blocked), steps_(kBlockStrides), strides_(kBlockStrides) {
    if (blocked.dims != geometry.dims || blocked.spacing != geometry.spacing)
      throw std::logic_error("VoxelGrid: the blocked volume is not of this volume's geometry");
  }

  const Volume& geometry() const { return volume_; }
  const BlockedVolume* blocks() const { return blocked_; }

  // Voxel v (inside the volume). From it, `steps` lead to a cell's far corners (0 along a
  // one-voxel axis of a flat volume) and `strides` to the next voxel along each axis, as far as
  // `reaches` says.
  const Voxel* address(glm::ivec3 v) const {
    if (!blocked_) return volume_.voxels.data() + volume_.indexOf(v.x, v.y, v.z);
    const glm::ivec3 block = v / kBlockSize;
    return blocked_->blockVoxels(blocked_->blockIndex(block)) +
           BlockedVolume::localIndex(v - BlockedVolume::windowOrigin(block));
  }
  glm::ivec3 steps() const { return steps_; }
  glm::ivec3 strides() const { return strides_; }
  // Whether the voxels v - below .. v + above (below <= 1, above <= 2) along each axis can be read
  // from address(v) through strides: always in a block's window; not at a flat volume's faces,
  // where the clamped functions of core/volume_sampling.h must be used.
  bool reaches(glm::ivec3 v, int below, int above) const {
    return blocked_ || hasAllNeighbours(volume_, v, below, above);
  }

  Voxel at(glm::ivec3 v) const {
    return blocked_ ? blocked_->voxel(v.x, v.y, v.z) : volume_.at(v.x, v.y, v.z);
  }

  // Strides through a block's window.
  static constexpr glm::ivec3 kBlockStrides{1, kStoredBlockSize, kStoredBlockSize* kStoredBlockSize};

 private:
  const Volume& volume_;
  const BlockedVolume* blocked_ = nullptr;
  glm::ivec3 steps_, strides_;
};

// VoxelGrid::address for the voxels of one ray, which stay in one block for many samples in a
// row: a block's voxels are looked up when the ray enters it, not at every voxel.
class VoxelCursor {
 public:
  explicit VoxelCursor(const VoxelGrid& grid) : grid_(grid) {}

  const Voxel* address(glm::ivec3 v) {
    if (!grid_.blocks()) return grid_.address(v);
    const glm::ivec3 local = v - origin_;  // in [1, 32] along every axis inside the block's core
    if (glm::any(glm::lessThan(local, glm::ivec3(kBlockOverlapBelow))) ||
        glm::any(glm::greaterThanEqual(local, glm::ivec3(kBlockOverlapBelow + kBlockSize))))
      return enter(v);
    return voxels_ + BlockedVolume::localIndex(local);
  }

 private:
  // Out of line: once per block a ray enters, and the flat grid's loops stay as small as before.
  [[gnu::noinline]] const Voxel* enter(glm::ivec3 v) {
    const glm::ivec3 block = v / kBlockSize;
    const BlockedVolume& blocked = *grid_.blocks();
    voxels_ = blocked.blockVoxels(blocked.blockIndex(block));
    origin_ = BlockedVolume::windowOrigin(block);
    return voxels_ + BlockedVolume::localIndex(v - origin_);
  }

  const VoxelGrid& grid_;
  const Voxel* voxels_ = nullptr;  // the current block's window
  // Its first voxel; at first far below the volume, so that every voxel is outside the block.
  glm::ivec3 origin_{std::numeric_limits<int>::min() / 2};
};

// The filters of core/volume_sampling.h on either grid.

template <class Read = PlainDensity>
float trilinearDensity(const VoxelGrid& grid, const Cell& cell, const Read& read = {}) {
  return trilinearDensityAt(grid.address(cell.base), grid.steps(), cell, read);
}

template <class Read = PlainDensity>
glm::vec3 trilinearGradient(const VoxelGrid& grid, const Cell& cell, const Read& read = {}) {
  if (!grid.reaches(cell.base, 1, 2)) return trilinearGradient(grid.geometry(), cell, read);
  return trilinearGradientAt(grid.address(cell.base), grid.strides(), grid.geometry().spacing, cell,
                             read);
}

// The mean filter and the nearest voxel's gradient at voxel v, whose address (VoxelGrid::address
// or VoxelCursor::address) is `at`.
template <class Read = PlainDensity>
float meanDensity(const VoxelGrid& grid, glm::ivec3 v, const Voxel* at, const Read& read = {}) {
  if (!grid.reaches(v, 1, 1)) return meanDensity(grid.geometry(), v, read);
  return meanDensityInterior(at, grid.strides(), read);
}

template <class Read = PlainDensity>
glm::vec3 nearestGradient(const VoxelGrid& grid, glm::ivec3 v, const Voxel* at, const Read& read = {}) {
  if (!grid.reaches(v, 1, 1)) return nearestGradient(grid.geometry(), v, read);
  return voxelGradientInterior(at, grid.strides(), grid.geometry().spacing, read);
}

}  // namespace angio
