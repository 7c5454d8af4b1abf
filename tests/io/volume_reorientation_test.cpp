// Reorientation slab by slab: for every permutation and flip of the axes, copying the stored slices
// a few at a time puts every voxel where the plan says, as reading the whole array at once does.
#include "io/volume_reorientation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace angio {
namespace {

// Copies a row as it is, counting nothing as rejected.
struct CopyValues {
  std::size_t operator()(const int* first, std::ptrdiff_t step, int count, int* out) const {
    for (int x = 0; x < count; ++x) out[x] = first[x * step];
    return 0;
  }
};

// Every permutation of the three axes with every combination of flips.
std::vector<Reorientation> everyPlan() {
  std::vector<Reorientation> plans;
  std::array<int, 3> axes{0, 1, 2};
  do {
    for (int flips = 0; flips < 8; ++flips) {
      Reorientation plan;
      plan.sourceAxis = axes;
      for (int axis = 0; axis < 3; ++axis) plan.flipped[axis] = (flips >> axis) & 1;
      plans.push_back(plan);
    }
  } while (std::next_permutation(axes.begin(), axes.end()));
  return plans;
}

TEST(VolumeReorientation, SlabsPutEveryVoxelWhereThePlanSays) {
  const glm::ivec3 stored(5, 4, 7);
  std::vector<int> source(std::size_t(stored.x) * stored.y * stored.z);
  for (std::size_t n = 0; n < source.size(); ++n) source[n] = int(n);
  for (const Reorientation& plan : everyPlan()) {
    glm::ivec3 dims;
    for (int axis = 0; axis < 3; ++axis) dims[axis] = stored[plan.sourceAxis[axis]];
    std::vector<int> target(source.size(), -1);
    const int slabSlices = 3;  // 7 slices: slabs of 3, 3 and 1
    for (int first = 0; first < stored.z; first += slabSlices) {
      const int count = std::min(slabSlices, stored.z - first);
      const int* slab = source.data() + std::size_t(first) * stored.x * stored.y;
      reorientSlab(slab, stored, first, count, plan, target.data(), CopyValues{});
    }
    // The stored index of each new voxel, axis by axis, independently of the copy's strides.
    for (int k = 0; k < dims.z; ++k)
      for (int j = 0; j < dims.y; ++j)
        for (int i = 0; i < dims.x; ++i) {
          const glm::ivec3 index(i, j, k);
          glm::ivec3 from;
          for (int axis = 0; axis < 3; ++axis) {
            const int s = plan.sourceAxis[axis];
            from[s] = plan.flipped[axis] ? stored[s] - 1 - index[axis] : index[axis];
          }
          const int expected = (from.z * stored.y + from.y) * stored.x + from.x;
          ASSERT_EQ(target[(std::size_t(k) * dims.y + j) * dims.x + i], expected)
              << "axes " << plan.sourceAxis[0] << plan.sourceAxis[1] << plan.sourceAxis[2] << " flips "
              << plan.flipped[0] << plan.flipped[1] << plan.flipped[2] << " at " << i << "," << j << ","
              << k;
        }
  }
}

}  // namespace
}  // namespace angio
