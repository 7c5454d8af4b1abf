#pragma once
// A volume of unit spacing whose every voxel holds one raw value (density and label bits).
#include <glm/glm.hpp>

#include "core/volume.h"

namespace angio::test_support {

inline Volume filledVolume(glm::ivec3 dims, int voxel) {
  Volume volume;
  volume.dims = dims;
  volume.spacing = glm::dvec3(1.0);
  volume.voxels.assign(std::size_t(dims.x) * dims.y * dims.z, Voxel(voxel));
  return volume;
}

}  // namespace angio::test_support
