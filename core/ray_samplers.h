#pragma once
// Reconstruction along a ray for the fast raycaster: one type per filter, so the inner loop is
// compiled once per filter without a branch on it. Each gives the bits of core/volume_sampling.h's
// sampleDensity / sampleGradient (the reference's path): the same voxels, the same operations in
// the same order.
//
// The trilinear sampler keeps the thesis's cell cache (sec. 4.3.4): the eight corner densities of
// the ray's current cell with their min/max, and, from the first visible sample in the cell on, the
// eight corner gradients. At the high level (osd 0.3) about three consecutive samples share a cell,
// so a cell's voxels are read once, and a sample in a cell whose densities the TF hides costs one
// O(1) query of the integrated opacity table instead of an interpolation (cell transparency: a
// trilinear value lies between the corners' min and max, so its table entry does too).
//
// Use per sample: moveTo(q), then mayBeVisible / maxDensity, then density(fracA), then
// gradient(fracA); densityAt(q, fracA) reads another position without moving (pre-integration's
// front sample). Rows of a bundle (core/fast_raycaster.cpp) share one sampler: their samples
// read the same voxels and differ only in the cell fraction along the rotation axis a, `fracA`
// (what cellAt gives for the row's own q; the voxel filters ignore it, a bundle's rows read the
// same nearest voxel). samplesLeftInCell() tells how many of the following samples (q + j step, j = 1, 2, ...)
// surely fall into the same cell (the same voxels), so a ray can leap over a hidden cell at once
// (0 where the sampler does not know). `Read` turns voxels into densities (PlainDensity, or
// MaskedDensity where labels are hidden); label(fracA) is the label of the sample's nearest voxel,
// which picks its TF (rendering model, "Labels").
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include <glm/glm.hpp>

#include "core/transfer_function.h"
#include "core/volume.h"
#include "core/volume_sampling.h"
#include "core/voxel_grid.h"

namespace angio {

// Both filters that read around the nearest voxel; the gradient is the nearest voxel's.
// Mean (thesis sec. 4.4): the nearest voxel and its six face neighbours.
enum class VoxelFilter { nearest, mean };

template <VoxelFilter Filter, class ReadDensity>
class VoxelRaySampler {
 public:
  using Read = ReadDensity;
  VoxelRaySampler(const VoxelGrid& grid, const glm::dvec3&, int, const Read& read = {})
      : grid_(grid), volume_(grid.geometry()), read_(read), cursor_(grid) {}

  void moveTo(const glm::dvec3& q) {
    voxel_ = nearestVoxel(volume_, q);
    at_ = cursor_.address(voxel_);
  }
  bool mayBeVisible(const TfTable&) const { return true; }
  glm::ivec2 densityRange() const { return {0, kDensityLevels - 1}; }
  float maxDensity() const { return 4095.f; }
  long samplesLeftInCell() const { return 0; }
  float density(float) const { return densityOf(voxel_, at_); }
  float densityAt(const glm::dvec3& q, float) const {
    const glm::ivec3 v = nearestVoxel(volume_, q);
    return densityOf(v, grid_.address(v));
  }
  glm::vec3 gradientAt(const glm::dvec3& q, float) const {
    const glm::ivec3 v = nearestVoxel(volume_, q);
    return nearestGradient(grid_, v, grid_.address(v), read_);
  }
  glm::vec3 gradient(float) const { return nearestGradient(grid_, voxel_, at_, read_); }
  int label(float) const { return labelOf(*at_); }

 private:
  // Voxel v's density with the filter; `at` is its address.
  float densityOf(glm::ivec3 v, const Voxel* at) const {
    if constexpr (Filter == VoxelFilter::mean) return meanDensity(grid_, v, at, read_);
    else return float(read_(*at));
  }

  const VoxelGrid& grid_;
  const Volume& volume_;  // the geometry
  const Read read_;
  VoxelCursor cursor_;
  glm::ivec3 voxel_{0};
  const Voxel* at_ = nullptr;  // voxel_'s address
};

template <class Read>
using NearestRaySampler = VoxelRaySampler<VoxelFilter::nearest, Read>;
template <class Read>
using MeanRaySampler = VoxelRaySampler<VoxelFilter::mean, Read>;

template <class ReadDensity>
class TrilinearRaySampler {
 public:
  using Read = ReadDensity;
  // `step`: from one sample of the ray to the next, in voxel units; `axis`: the rotation axis a.
  TrilinearRaySampler(const VoxelGrid& grid, const glm::dvec3& step, int axis, const Read& read = {})
      : grid_(grid), volume_(grid.geometry()), read_(read), steps_(grid.steps()),
        strides_(grid.strides()), axis_(axis) {
    for (int axis = 0; axis < 3; ++axis) {
      forward_[axis] = step[axis] > 0;
      inverseStep_[axis] = step[axis] != 0 ? 1.0 / std::abs(step[axis]) : 0.0;
    }
  }

  void moveTo(const glm::dvec3& q) {
    q_ = q;
    cell_ = cellAt(volume_, q);
    densityPlanes_.ready = gradientPlanes_.ready = false;
    if (cell_.base != cached_) load();
  }
  bool mayBeVisible(const TfTable& table) const { return table.anyVisible(lo_, hi_); }
  // The smallest and largest corner density: every sample in the cell lies between them.
  glm::ivec2 densityRange() const { return {lo_, hi_}; }
  float maxDensity() const { return float(hi_); }

  // The j >= 1 with base <= q + j step < base + 1 on every axis, less a margin far above the
  // rounding of the sample positions (1e-7 voxel), so the count never includes a sample of the
  // next cell. (Conservative at the volume's last cell, whose far face cellAt also includes.)
  long samplesLeftInCell() const {
    double limit = 1e18;
    for (int axis = 0; axis < 3; ++axis) {
      if (inverseStep_[axis] == 0) continue;
      const double room = forward_[axis] ? cached_[axis] + 1 - q_[axis] : q_[axis] - cached_[axis];
      limit = std::min(limit, room * inverseStep_[axis]);
    }
    return std::max(long(std::ceil(limit - 1e-7)) - 1, 0L);
  }
  // About the rotation axis k (the patient's long axis, the default) the rows of a bundle differ
  // only in the last of trilinear's interpolations, along z: the two bilinear planes are computed
  // once per sample for all rows.
  float density(float fracA) {
    return interpolateRow(
        fracA, [&](int dx, int dy, int dz) { return corners_[corner(dx, dy, dz)]; }, densityPlanes_);
  }
  // The density of this row at another position of the ray (q as given to moveTo), without moving:
  // pre-integration's front sample where the ray did not evaluate the sample before.
  float densityAt(const glm::dvec3& q, float fracA) const {
    Cell cell = cellAt(volume_, q);
    cell.frac[axis_] = fracA;
    return trilinearDensity(grid_, cell, read_);
  }
  glm::vec3 gradientAt(const glm::dvec3& q, float fracA) const {
    Cell cell = cellAt(volume_, q);
    cell.frac[axis_] = fracA;
    return trilinearGradient(grid_, cell, read_);
  }
  glm::vec3 gradient(float fracA) {
    if (!gradientsLoaded_) loadGradients();
    return interpolateRow(
        fracA, [&](int dx, int dy, int dz) { return gradients_[corner(dx, dy, dz)]; }, gradientPlanes_);
  }
  // The nearest corner (nearestCorner in core/volume_sampling.h) as this row sees the cell.
  int label(float fracA) const {
    static_assert(!std::is_same_v<Read, PlainDensity>, "labels are read only on the labelled path");
    int index = 0;  // corner(dx, dy, dz) has one bit per axis
    for (int axis = 0; axis < 3; ++axis)
      index |= int((axis == axis_ ? fracA : cell_.frac[axis]) >= 0.5f) << axis;
    return cornerLabels_[index];
  }

 private:
  static int corner(int dx, int dy, int dz) { return dx + 2 * dy + 4 * dz; }

  // The current cell as one row of the bundle sees it.
  Cell rowCell(float fracA) const {
    Cell cell = cell_;
    cell.frac[axis_] = fracA;
    return cell;
  }

  // The current sample's two bilinear planes z = base and base + 1, kept until the next moveTo.
  template <class T>
  struct Planes {
    bool ready = false;
    std::array<T, 2> value{};
  };

  // trilinear() of the corner values for one row of the bundle; about k through `planes`.
  template <class CornerValue, class T>
  T interpolateRow(float fracA, CornerValue&& corners, Planes<T>& planes) const {
    if (axis_ != 2) return trilinear(rowCell(fracA), corners);
    if (!planes.ready) {
      planes.value = {bilinearInPlane(cell_, corners, 0), bilinearInPlane(cell_, corners, 1)};
      planes.ready = true;
    }
    return interpolate(planes.value[0], planes.value[1], fracA);
  }

  void load() {
    cached_ = cell_.base;
    gradientsLoaded_ = false;
    base_ = grid_.address(cached_);
    const Voxel* base = base_;
    const glm::ivec3 steps = steps_;
    int lo = 4095, hi = 0;
    for (int dz = 0; dz < 2; ++dz)
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const Voxel v = base[dx * steps.x + dy * steps.y + dz * steps.z];
          const int d = read_(v);
          corners_[corner(dx, dy, dz)] = float(d);
          // Labels pick TFs only on the labelled path; the plain one does not pay for them.
          if constexpr (!std::is_same_v<Read, PlainDensity>)
            cornerLabels_[corner(dx, dy, dz)] = std::uint8_t(labelOf(v));
          lo = std::min(lo, d);
          hi = std::max(hi, d);
        }
    lo_ = lo;
    hi_ = hi;
  }

  // As trilinearGradient computes each corner's central differences (volume_sampling.h). Where the
  // shell can be read (everywhere but at a flat volume's faces) half of the 48 neighbours are the
  // cell's own corners, already in corners_ (the same float values), so only the 24 voxels of the
  // shell around the cell are read.
  void loadGradients() {
    gradientsLoaded_ = true;
    if (grid_.reaches(cached_, 1, 2)) {
      const Voxel* base = base_;
      const glm::ivec3 strides = strides_;
      for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            const Voxel* v = base + dx * strides.x + dy * strides.y + dz * strides.z;
            const glm::ivec3 d(dx, dy, dz);
            glm::vec3 g;
            for (int axis = 0; axis < 3; ++axis) {
              // The neighbour inside the cell is the corner across it; the other is in the shell.
              glm::ivec3 across = d;
              across[axis] = 1 - d[axis];
              const float inside = corners_[corner(across.x, across.y, across.z)];
              const float shell = float(read_(v[d[axis] ? strides[axis] : -strides[axis]]));
              g[axis] = d[axis] ? centralDifference(inside, shell, volume_.spacing[axis])
                                : centralDifference(shell, inside, volume_.spacing[axis]);
            }
            gradients_[corner(dx, dy, dz)] = g;
          }
      return;
    }
    for (int dz = 0; dz < 2; ++dz)
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx)
          gradients_[corner(dx, dy, dz)] =
              voxelGradient(volume_, clampIndex(volume_, cached_ + glm::ivec3(dx, dy, dz)), read_);
  }

  const VoxelGrid& grid_;
  const Volume& volume_;  // the geometry; its voxels are read only through grid_
  const Read read_;
  const glm::ivec3 steps_, strides_;  // the grid's
  const int axis_;
  glm::dvec3 inverseStep_{0.0};  // 1 / |step| per axis, 0 where the ray does not move along it
  glm::bvec3 forward_{false};
  Cell cell_;
  glm::dvec3 q_{0.0};
  glm::ivec3 cached_{-1};
  const Voxel* base_ = nullptr;  // the voxel cached_ (VoxelGrid::address)
  bool gradientsLoaded_ = false;
  int lo_ = 0, hi_ = 0;
  std::array<float, 8> corners_;  // filled by load() before any use
  std::array<std::uint8_t, 8> cornerLabels_;
  std::array<glm::vec3, 8> gradients_;  // filled by loadGradients() before any use
  Planes<float> densityPlanes_;         // rotation about k
  Planes<glm::vec3> gradientPlanes_;
};

}  // namespace angio
