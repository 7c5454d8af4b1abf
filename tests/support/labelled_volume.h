#pragma once
// Labels for rendering tests: every voxel (i, j, k) of density `hu` gets labelAt(i, j, k, hu)
// (0: none) in its label bits, its density kept.
#include "core/volume.h"

namespace angio::test_support {

template <class LabelAt>
void labelVoxels(Volume& volume, LabelAt&& labelAt) {
  for (int k = 0; k < volume.dims.z; ++k)
    for (int j = 0; j < volume.dims.y; ++j)
      for (int i = 0; i < volume.dims.x; ++i) {
        Voxel& v = volume.voxels[volume.indexOf(i, j, k)];
        v = Voxel(densityOf(v) | labelAt(i, j, k, huOfDensity(densityOf(v))) << 12);
      }
}

}  // namespace angio::test_support
