#pragma once
// Reconstruction of density and gradient at a continuous voxel coordinate q = p / spacing
// (rendering model, "Sampling"). Indices are clamped to the volume, so these never read outside it.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "core/render_params.h"
#include "core/volume.h"

namespace angio {

inline glm::ivec3 clampIndex(const Volume& volume, glm::ivec3 index) {
  return glm::clamp(index, glm::ivec3(0), volume.dims - 1);
}

inline float densityAtClamped(const Volume& volume, glm::ivec3 index) {
  const glm::ivec3 c = clampIndex(volume, index);
  return float(volume.densityAt(c.x, c.y, c.z));
}

// Nearest voxel: floor(q + 0.5).
inline glm::ivec3 nearestVoxel(const Volume& volume, glm::dvec3 q) {
  return clampIndex(volume, glm::ivec3(glm::floor(q + 0.5)));
}

// Central differences at a voxel, in density units (= HU) per mm, neighbours clamped.
inline glm::vec3 voxelGradient(const Volume& volume, glm::ivec3 v) {
  glm::vec3 g;
  for (int axis = 0; axis < 3; ++axis) {
    glm::ivec3 lo = v, hi = v;
    --lo[axis];
    ++hi[axis];
    g[axis] = (densityAtClamped(volume, hi) - densityAtClamped(volume, lo)) /
              float(2.0 * volume.spacing[axis]);
  }
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

template <typename CornerValue>
auto trilinear(const Cell& cell, CornerValue&& corner) {
  const glm::vec3 f = cell.frac;
  auto lerp = [](auto a, auto b, float t) { return a + (b - a) * t; };
  auto value = [&](int dx, int dy, int dz) { return corner(cell.base + glm::ivec3(dx, dy, dz)); };
  const auto x00 = lerp(value(0, 0, 0), value(1, 0, 0), f.x);
  const auto x10 = lerp(value(0, 1, 0), value(1, 1, 0), f.x);
  const auto x01 = lerp(value(0, 0, 1), value(1, 0, 1), f.x);
  const auto x11 = lerp(value(0, 1, 1), value(1, 1, 1), f.x);
  return lerp(lerp(x00, x10, f.y), lerp(x01, x11, f.y), f.z);
}

// Density (0..4095, fractional for trilinear and mean) reconstructed with the filter.
inline float sampleDensity(const Volume& volume, glm::dvec3 q, Filter filter) {
  switch (filter) {
    case Filter::nearest: {
      const glm::ivec3 v = nearestVoxel(volume, q);
      return float(volume.densityAt(v.x, v.y, v.z));
    }
    case Filter::mean: {
      // Thesis sec. 4.4: the nearest voxel and its 6 face neighbours, equally weighted.
      const glm::ivec3 v = nearestVoxel(volume, q);
      float sum = densityAtClamped(volume, v);
      for (int axis = 0; axis < 3; ++axis) {
        glm::ivec3 lo = v, hi = v;
        --lo[axis];
        ++hi[axis];
        sum += densityAtClamped(volume, lo) + densityAtClamped(volume, hi);
      }
      return sum / 7.f;
    }
    case Filter::trilinear:
      return trilinear(cellAt(volume, q),
                       [&](glm::ivec3 v) { return densityAtClamped(volume, v); });
  }
  return 0.f;
}

// Gradient reconstructed with the same filter as the density (for mean: the nearest voxel's).
inline glm::vec3 sampleGradient(const Volume& volume, glm::dvec3 q, Filter filter) {
  if (filter == Filter::trilinear)
    return trilinear(cellAt(volume, q), [&](glm::ivec3 v) {
      return voxelGradient(volume, clampIndex(volume, v));
    });
  return voxelGradient(volume, nearestVoxel(volume, q));
}

}  // namespace angio
