#pragma once
// The contrast-filled lumen of a box of the volume, as vessel tracing sees it: which voxels hold
// contrast (density in a range, not labelled bone or table) and, for each, the distance to the
// nearest voxel that does not (ITK's SignedMaurerDistanceMapImageFilter, exact Euclidean, in mm).
// The distance map's ridge is the centerline in vmtk's sense (centres of maximal inscribed
// spheres); minimal paths follow it and snapped clicks climb to it.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/volume.h"

namespace angio {

// The densities (HU) that count as contrast-filled lumen.
struct ContrastRange {
  double lowHu = 0, highHu = 0;

  friend bool operator==(const ContrastRange&, const ContrastRange&) = default;
};

// The range a lumen of `lumenHu` implies: from halfway between it and soft tissue (the lumen's
// wall at half maximum) up to where calcium begins, by default twice as far above the lumen, so
// calcified plaque and cortical bone stay out.
ContrastRange contrastRangeFor(double lumenHu, double tissueHu,
                               std::optional<double> calciumHu = std::nullopt);

// A box of voxels, lo and hi inclusive; empty when any hi < lo.
struct VoxelBox {
  glm::ivec3 lo{0}, hi{-1};

  friend bool operator==(const VoxelBox&, const VoxelBox&) = default;
};

bool isEmpty(const VoxelBox& box);
glm::ivec3 sizeOf(const VoxelBox& box);
bool contains(const VoxelBox& box, glm::ivec3 voxel);
// The whole volume.
VoxelBox wholeVolume(const Volume& volume);
// The box around points (volume frame, mm) grown by marginMm, clipped to the volume.
VoxelBox boxAround(const Volume& volume, const std::vector<glm::dvec3>& pointsMm, double marginMm);
bool containsBox(const VoxelBox& outer, const VoxelBox& inner);

class LumenField {
 public:
  LumenField() = default;
  // Empty (isReady() false) when `cancel` turned true.
  LumenField(const Volume& volume, ContrastRange range, VoxelBox box,
             const std::atomic<bool>* cancel = nullptr);

  bool isReady() const { return distanceMm_ != nullptr; }
  // The box asked for: its voxels outside box() are not lumen.
  const VoxelBox& coverage() const { return coverage_; }
  // The box the map is stored for: around the lumen voxels of the coverage.
  const VoxelBox& box() const { return box_; }
  const ContrastRange& range() const { return range_; }
  glm::dvec3 spacing() const { return spacing_; }

  bool inBox(glm::ivec3 voxel) const { return contains(box_, voxel); }
  // 0 outside the lumen and outside the box.
  float wallDistanceMm(glm::ivec3 voxel) const {
    return inBox(voxel) ? distanceMm_.get()[offsetOf(voxel)] : 0.0f;
  }
  bool isLumen(glm::ivec3 voxel) const { return wallDistanceMm(voxel) > 0; }

  // Linear offset of a voxel of the box (box-local, i fastest) and back.
  std::size_t offsetOf(glm::ivec3 voxel) const {
    const glm::ivec3 local = voxel - box_.lo;
    return (std::size_t(local.z) * size_.y + local.y) * size_.x + local.x;
  }
  glm::ivec3 voxelOf(std::size_t offset) const;
  std::size_t voxelCount() const { return count_; }
  float wallDistanceAt(std::size_t offset) const { return distanceMm_.get()[offset]; }

 private:
  VoxelBox coverage_, box_;
  glm::ivec3 size_{0};
  glm::dvec3 spacing_{1.0};
  ContrastRange range_;
  std::size_t count_ = 0;
  std::shared_ptr<const float>
      distanceMm_;  // per voxel of the box; 0 = not lumen (shared: copies are cheap)
};

}  // namespace angio
