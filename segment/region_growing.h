#pragma once
// Interactive labelling, as clinicians know it from Horos: from the voxel under a click, the
// connected structure in an HU range (face neighbours, ITK's ConnectedThresholdImageFilter), with
// the holes it encloses (a bone's marrow inside its cortex) filled; and the connected piece of one
// label, to give it back. Voxels of other labels are never taken.
#include <atomic>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "core/volume.h"

namespace angio {

struct GrowSettings {
  double lowHu = 500, highHu = 3071;
  int label = 1;          // the label the region is for: its voxels and unlabelled ones may join
  bool fillHoles = true;  // enclosed holes of the region join it (within its bounding box)

  friend bool operator==(const GrowSettings&, const GrowSettings&) = default;
};

// Indices (Volume::voxels' order, ascending) of the voxels connected to `seed` whose HU is in the
// range and whose label is 0 or settings.label; none if the seed itself is not. Empty when
// `cancel` turns true.
std::vector<std::size_t> growRegion(const Volume& volume, glm::ivec3 seed, const GrowSettings& settings,
                                    const std::atomic<bool>* cancel = nullptr);

// Indices of the voxels connected to `seed` (face neighbours) that carry its label; none for an
// unlabelled seed.
std::vector<std::size_t> connectedLabelled(const Volume& volume, glm::ivec3 seed,
                                           const std::atomic<bool>* cancel = nullptr);

}  // namespace angio
