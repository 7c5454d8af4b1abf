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

// Copies the stored slices [firstSlice, firstSlice + sliceCount) (stored k) of a stored voxel
// array (i fastest), given as `slab` holding just those slices, into their places in the
// reoriented array `target` (the whole volume). A volume can so be read slab by slab without ever
// holding all of its stored voxels. For each output row (or the part of it the slab holds),
// convertRow(const Source* first, std::ptrdiff_t step, int count, Target* out) reads `count` source
// values `step` apart and returns how many it had to reject (e.g. NaN); the sum is returned.
template <class Source, class Target, class ConvertRow>
std::size_t reorientSlab(const Source* slab, glm::ivec3 storedDims, int firstSlice, int sliceCount,
                         const Reorientation& plan, Target* target, ConvertRow convertRow) {
  const std::array<std::ptrdiff_t, 3> storedStride{1, std::ptrdiff_t(storedDims.x),
                                                   std::ptrdiff_t(storedDims.x) * storedDims.y};
  // Source offset (from the slab's first voxel) of new voxel (0,0,0), the source step along each
  // new axis, and the new voxels the slab holds: [lo, hi) along each new axis.
  std::ptrdiff_t start = -std::ptrdiff_t(firstSlice) * storedStride[2];
  std::array<std::ptrdiff_t, 3> step{};
  glm::ivec3 dims, lo(0), hi;
  for (int axis = 0; axis < 3; ++axis) {
    const int from = plan.sourceAxis[axis];
    dims[axis] = storedDims[from];
    step[axis] = plan.flipped[axis] ? -storedStride[from] : storedStride[from];
    if (plan.flipped[axis]) start += (storedDims[from] - 1) * storedStride[from];
    lo[axis] = 0;
    hi[axis] = dims[axis];
    if (from == 2) {
      const int last = firstSlice + sliceCount;  // stored slices [firstSlice, last)
      lo[axis] = plan.flipped[axis] ? dims[axis] - last : firstSlice;
      hi[axis] = plan.flipped[axis] ? dims[axis] - firstSlice : last;
    }
  }
  const std::ptrdiff_t rowsJ = hi.y - lo.y, rows = rowsJ * (hi.z - lo.z);
  return tbb::parallel_reduce(
      tbb::blocked_range<std::ptrdiff_t>(0, rows, 64), std::size_t{0},
      [&](const tbb::blocked_range<std::ptrdiff_t>& range, std::size_t rejected) {
        for (std::ptrdiff_t row = range.begin(); row != range.end(); ++row) {
          const std::ptrdiff_t j = lo.y + row % rowsJ, k = lo.z + row / rowsJ;
          // The offset is summed first: partial sums may point outside the slab.
          const std::ptrdiff_t offset = start + lo.x * step[0] + j * step[1] + k * step[2];
          const Source* first = slab + offset;
          Target* out = target + (k * dims.y + j) * std::ptrdiff_t(dims.x) + lo.x;
          rejected += convertRow(first, step[0], hi.x - lo.x, out);
        }
        return rejected;
      },
      [](std::size_t a, std::size_t b) { return a + b; });
}

// The same for the whole stored array at once.
template <class Source, class Target, class ConvertRow>
std::size_t reorientCopy(const Source* source, glm::ivec3 storedDims, const Reorientation& plan,
                         Target* target, ConvertRow convertRow) {
  return reorientSlab(source, storedDims, 0, storedDims.z, plan, target, convertRow);
}

}  // namespace angio
