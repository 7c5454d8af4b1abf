#pragma once
// Reorientation to the rendering model's LPS-aligned frame (rendering-model.md, "Volume frame"):
// each stored voxel axis goes to the LPS axis its direction cosine is closest to, flipped to point
// positive. Voxels are permuted and flipped to match, and `direction` keeps the residual rotation so
// that physical points still map to the right voxels.
#include <array>
#include <cstddef>

#include <glm/glm.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace angio {

// Where voxels sit in space: physical (mm, LPS) = origin + direction * (index * spacing).
struct VolumeGeometry {
  glm::ivec3 dims{0};
  glm::dvec3 spacing{1.0};    // mm
  glm::dvec3 origin{0.0};     // mm, LPS
  glm::dmat3 direction{1.0};  // columns: unit directions of voxel axes i, j, k
};

struct Reorientation {
  std::array<int, 3> sourceAxis{0, 1, 2};  // for new axis L, P, S: the stored voxel axis
  std::array<bool, 3> flipped{};           // that stored axis points along -L, -P or -S
  double obliqueDegrees = 0.0;             // largest angle between a stored axis and its LPS axis

  bool movesVoxels() const;
};

// Axes snap to LPS by largest |cosine| first, so two stored axes never claim the same LPS axis.
// Throws std::invalid_argument for a degenerate direction (zero, non-finite or parallel axes).
Reorientation planReorientation(const glm::dmat3& direction);

// The geometry after reorientation: dims and spacing permuted, origin at the physical position of
// the new voxel (0, 0, 0), direction = the residual rotation (exactly identity if within 1e-6).
VolumeGeometry reorientedGeometry(const VolumeGeometry& stored, const Reorientation& plan);

// Copies a stored voxel array (i fastest) into reoriented order. For each output row,
// convertRow(const Source* first, std::ptrdiff_t step, int count, Target* out) reads `count`
// source values `step` apart and returns how many it had to reject (e.g. NaN); the sum is returned.
template <class Source, class Target, class ConvertRow>
std::size_t reorientCopy(const Source* source, glm::ivec3 storedDims, const Reorientation& plan,
                         Target* target, ConvertRow convertRow) {
  const std::array<std::ptrdiff_t, 3> storedStride{1, std::ptrdiff_t(storedDims.x),
                                                   std::ptrdiff_t(storedDims.x) * storedDims.y};
  // Source offset of new voxel (0,0,0), and the source step along each new axis.
  std::ptrdiff_t start = 0;
  std::array<std::ptrdiff_t, 3> step{};
  glm::ivec3 dims;
  for (int axis = 0; axis < 3; ++axis) {
    const int from = plan.sourceAxis[axis];
    dims[axis] = storedDims[from];
    step[axis] = plan.flipped[axis] ? -storedStride[from] : storedStride[from];
    if (plan.flipped[axis]) start += (storedDims[from] - 1) * storedStride[from];
  }
  const std::ptrdiff_t rows = std::ptrdiff_t(dims.y) * dims.z;
  return tbb::parallel_reduce(
      tbb::blocked_range<std::ptrdiff_t>(0, rows, 64), std::size_t{0},
      [&](const tbb::blocked_range<std::ptrdiff_t>& range, std::size_t rejected) {
        for (std::ptrdiff_t row = range.begin(); row != range.end(); ++row) {
          const std::ptrdiff_t j = row % dims.y, k = row / dims.y;
          const Source* first = source + start + j * step[1] + k * step[2];
          rejected += convertRow(first, step[0], dims.x, target + row * dims.x);
        }
        return rejected;
      },
      [](std::size_t a, std::size_t b) { return a + b; });
}

}  // namespace angio
