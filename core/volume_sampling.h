#pragma once
// Reconstruction of density and gradient at a continuous voxel coordinate q = p / spacing
// (rendering model, "Sampling"). Indices are clamped to the volume, so these never read outside it.
// `read` turns a voxel into its density: PlainDensity, or MaskedDensity (core/label_tables.h) where
// hidden labels read as density 0 for the density, the gradient and MIP alike.
// Hot paths address voxels through pointer offsets; border cases take the clamped path, which
// computes the same values (clamping changes nothing inside the volume).
#include <algorithm>
#include <cmath>
#include <cstddef>

#include <glm/glm.hpp>

#include "core/render_params.h"
#include "core/volume.h"

namespace angio {

inline glm::ivec3 clampIndex(const Volume& volume, glm::ivec3 index) {
  return glm::clamp(index, glm::ivec3(0), volume.dims - 1);
}

template <class Read = PlainDensity>
float densityAtClamped(const Volume& volume, glm::ivec3 index, const Read& read = {}) {
  const glm::ivec3 c = clampIndex(volume, index);
  return float(read(volume.at(c.x, c.y, c.z)));
}

inline glm::ivec3 voxelStrides(const Volume& volume) {
  return {1, volume.dims.x, volume.dims.x * volume.dims.y};
}

// Nearest voxel: floor(q + 0.5).
inline glm::ivec3 nearestVoxel(const Volume& volume, glm::dvec3 q) {
  return clampIndex(volume, glm::ivec3(glm::floor(q + 0.5)));
}

inline bool hasAllNeighbours(const Volume& volume, glm::ivec3 v, int below, int above) {
  return glm::all(glm::greaterThanEqual(v, glm::ivec3(below))) &&
         glm::all(glm::lessThan(v + above, volume.dims));
}

// Central difference along one axis from the two neighbour densities, in HU per mm. A multiply
// by 1 / (2 spacing), not a divide: a gradient costs 24 of these per cell at the high level.
inline float centralDifference(float below, float above, double spacing) {
  return (above - below) * float(0.5 / spacing);
}

// Central differences at a voxel, neighbours clamped.
template <class Read = PlainDensity>
glm::vec3 voxelGradient(const Volume& volume, glm::ivec3 v, const Read& read = {}) {
  glm::vec3 g;
  for (int axis = 0; axis < 3; ++axis) {
    glm::ivec3 lo = v, hi = v;
    --lo[axis];
    ++hi[axis];
    g[axis] = centralDifference(densityAtClamped(volume, lo, read), densityAtClamped(volume, hi, read),
                                volume.spacing[axis]);
  }
  return g;
}

// The same for a voxel whose six neighbours exist, through pointer offsets.
template <class Read = PlainDensity>
glm::vec3 voxelGradientInterior(const Voxel* voxel, glm::ivec3 strides, glm::dvec3 spacing,
                                const Read& read = {}) {
  glm::vec3 g;
  for (int axis = 0; axis < 3; ++axis)
    g[axis] = centralDifference(float(read(voxel[-strides[axis]])), float(read(voxel[strides[axis]])),
                                spacing[axis]);
  return g;
}

// The cell corner below q and the fractional position inside the cell, for trilinear weights.
struct Cell {
  glm::ivec3 base{0};
  glm::vec3 frac{0.f};
};

inline Cell cellAt(const Volume& volume, glm::dvec3 q) {
  Cell cell;
  for (int axis = 0; axis < 3; ++axis) {
    const int lastBase = std::max(volume.dims[axis] - 2, 0);
    const double clamped = std::clamp(q[axis], 0.0, double(volume.dims[axis] - 1));
    cell.base[axis] = std::min(int(std::floor(clamped)), lastBase);
    cell.frac[axis] = float(clamped - cell.base[axis]);
  }
  return cell;
}

// a + (b - a) t with one rounding (a fused multiply-add), whatever the compiler would contract:
// the reference, the fast raycaster and its SIMD lanes (core/sample_batch.h) get the same bits.
inline float interpolate(float a, float b, float t) { return std::fma(b - a, t, a); }
inline glm::vec3 interpolate(const glm::vec3& a, const glm::vec3& b, float t) {
  return {interpolate(a.x, b.x, t), interpolate(a.y, b.y, t), interpolate(a.z, b.z, t)};
}

// corner(dx, dy, dz) gives the value at base + (dx, dy, dz). The bilinear value in the cell's
// plane dz: along x, then y.
template <typename CornerValue>
auto bilinearInPlane(const Cell& cell, CornerValue&& corner, int dz) {
  const glm::vec3 f = cell.frac;
  return interpolate(interpolate(corner(0, 0, dz), corner(1, 0, dz), f.x),
                     interpolate(corner(0, 1, dz), corner(1, 1, dz), f.x), f.y);
}

// Along x, then y, then z: the order is fixed, so every caller gets the same bits for the same
// corner values (the fast raycaster shares the two planes between rows that differ only in z).
template <typename CornerValue>
auto trilinear(const Cell& cell, CornerValue&& corner) {
  return interpolate(bilinearInPlane(cell, corner, 0), bilinearInPlane(cell, corner, 1), cell.frac.z);
}

// Offsets to a cell's far corners; 0 along an axis of one voxel (then both corners coincide).
inline glm::ivec3 cornerSteps(const Volume& volume) {
  const glm::ivec3 strides = voxelStrides(volume);
  return {volume.dims.x > 1 ? strides.x : 0, volume.dims.y > 1 ? strides.y : 0,
          volume.dims.z > 1 ? strides.z : 0};
}

// The voxel nearest to the sample, floor(q + 0.5), as the cell's corner: per axis the far one
// where the fraction is at least 0.5 (the fraction in float, as trilinear weighs with it).
inline glm::ivec3 nearestCorner(const Cell& cell) {
  return cell.base + glm::ivec3(glm::greaterThanEqual(cell.frac, glm::vec3(0.5f)));
}

// Trilinear density of the cell whose base voxel is at `base`, its far corners `steps` away.
template <class Read = PlainDensity>
float trilinearDensityAt(const Voxel* base, glm::ivec3 steps, const Cell& cell, const Read& read = {}) {
  return trilinear(cell, [&](int dx, int dy, int dz) {
    return float(read(base[dx * steps.x + dy * steps.y + dz * steps.z]));
  });
}

template <class Read = PlainDensity>
float trilinearDensity(const Volume& volume, const Cell& cell, const Read& read = {}) {
  const Voxel* base = volume.voxels.data() + volume.indexOf(cell.base.x, cell.base.y, cell.base.z);
  return trilinearDensityAt(base, cornerSteps(volume), cell, read);
}

// Trilinear gradient of the cell whose base voxel is at `base`, where base - 1 .. base + 2 can be
// read through `strides` along every axis.
template <class Read = PlainDensity>
glm::vec3 trilinearGradientAt(const Voxel* base, glm::ivec3 strides, glm::dvec3 spacing,
                              const Cell& cell, const Read& read = {}) {
  return trilinear(cell, [&](int dx, int dy, int dz) {
    return voxelGradientInterior(base + dx * strides.x + dy * strides.y + dz * strides.z, strides,
                                 spacing, read);
  });
}

template <class Read = PlainDensity>
glm::vec3 trilinearGradient(const Volume& volume, const Cell& cell, const Read& read = {}) {
  if (hasAllNeighbours(volume, cell.base, 1, 2)) {
    const Voxel* base = volume.voxels.data() + volume.indexOf(cell.base.x, cell.base.y, cell.base.z);
    return trilinearGradientAt(base, voxelStrides(volume), volume.spacing, cell, read);
  }
  return trilinear(cell, [&](int dx, int dy, int dz) {
    return voxelGradient(volume, clampIndex(volume, cell.base + glm::ivec3(dx, dy, dz)), read);
  });
}

// The mean filter at a voxel whose six neighbours can be read through `strides`.
template <class Read = PlainDensity>
float meanDensityInterior(const Voxel* voxel, glm::ivec3 strides, const Read& read = {}) {
  float sum = float(read(*voxel));
  for (int axis = 0; axis < 3; ++axis)
    sum += float(read(voxel[-strides[axis]])) + float(read(voxel[strides[axis]]));
  return sum / 7.f;
}

// Thesis sec. 4.4: the nearest voxel and its 6 face neighbours, equally weighted.
template <class Read = PlainDensity>
float meanDensity(const Volume& volume, glm::ivec3 v, const Read& read = {}) {
  if (hasAllNeighbours(volume, v, 1, 1))
    return meanDensityInterior(volume.voxels.data() + volume.indexOf(v.x, v.y, v.z),
                               voxelStrides(volume), read);
  float sum = float(read(volume.at(v.x, v.y, v.z)));
  for (int axis = 0; axis < 3; ++axis) {
    glm::ivec3 lo = v, hi = v;
    --lo[axis];
    ++hi[axis];
    sum += densityAtClamped(volume, lo, read) + densityAtClamped(volume, hi, read);
  }
  return sum / 7.f;
}

template <class Read = PlainDensity>
glm::vec3 nearestGradient(const Volume& volume, glm::ivec3 v, const Read& read = {}) {
  if (hasAllNeighbours(volume, v, 1, 1))
    return voxelGradientInterior(volume.voxels.data() + volume.indexOf(v.x, v.y, v.z),
                                 voxelStrides(volume), volume.spacing, read);
  return voxelGradient(volume, v, read);
}

// Density (0..4095, fractional for trilinear and mean) reconstructed with the filter.
template <class Read = PlainDensity>
float sampleDensity(const Volume& volume, glm::dvec3 q, Filter filter, const Read& read = {}) {
  switch (filter) {
    case Filter::nearest: {
      const glm::ivec3 v = nearestVoxel(volume, q);
      return float(read(volume.at(v.x, v.y, v.z)));
    }
    case Filter::mean: return meanDensity(volume, nearestVoxel(volume, q), read);
    case Filter::trilinear: return trilinearDensity(volume, cellAt(volume, q), read);
  }
  return 0.f;
}

// Gradient reconstructed with the same filter as the density (for mean: the nearest voxel's).
template <class Read = PlainDensity>
glm::vec3 sampleGradient(const Volume& volume, glm::dvec3 q, Filter filter, const Read& read = {}) {
  if (filter == Filter::trilinear) return trilinearGradient(volume, cellAt(volume, q), read);
  return nearestGradient(volume, nearestVoxel(volume, q), read);
}

// The label that picks a sample's TF: its nearest voxel's (rendering model, "Labels").
inline int sampleLabel(const Volume& volume, glm::dvec3 q, Filter filter) {
  const glm::ivec3 v =
      filter == Filter::trilinear ? nearestCorner(cellAt(volume, q)) : nearestVoxel(volume, q);
  return labelOf(volume.at(v.x, v.y, v.z));
}

}  // namespace angio
