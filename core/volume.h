#pragma once
// A CT volume in the rendering model's frame: voxel axes i, j, k along +L, +P, +S, voxel centres at
// index * spacing (mm) relative to the first voxel. `origin` and `direction` keep the physical (LPS)
// placement so that points in mm (centerlines) map to voxels:
//   physical = origin + direction * (index * spacing).
// After reorientation `direction` is the identity for axis-aligned data; for an oblique
// acquisition (snapped to the nearest LPS axes for rendering, with a warning) it keeps the true
// residual rotation, which may be many degrees, so physicalToIndex stays exact.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/voxel.h"

namespace angio {

struct Volume {
  glm::ivec3 dims{0};
  glm::dvec3 spacing{1.0};    // mm per voxel step along i, j, k
  glm::dvec3 origin{0.0};     // physical position (mm, LPS) of voxel (0, 0, 0)
  glm::dmat3 direction{1.0};  // columns: physical direction of the i, j, k axes
  std::vector<Voxel> voxels;  // i fastest, then j, then k

  std::size_t voxelCount() const { return std::size_t(dims.x) * dims.y * dims.z; }
  std::size_t indexOf(int i, int j, int k) const { return (std::size_t(k) * dims.y + j) * dims.x + i; }
  Voxel at(int i, int j, int k) const { return voxels[indexOf(i, j, k)]; }
  int densityAt(int i, int j, int k) const { return densityOf(at(i, j, k)); }
};

// Allocates a volume of the given size filled with `fill`.
Volume makeVolume(glm::ivec3 dims, glm::dvec3 spacing, Voxel fill = encodeVoxel(-1024));

// The domain: the closed box of voxel centres, E = (n - 1) * spacing per axis (mm).
glm::dvec3 domainExtent(const Volume& volume);

// The voxel unit u = min(spacing) (mm); sampling distances are given in multiples of it.
double voxelUnit(const Volume& volume);

// Physical (mm, LPS) <-> continuous voxel index.
glm::dvec3 physicalToIndex(const Volume& volume, glm::dvec3 physical);
glm::dvec3 indexToPhysical(const Volume& volume, glm::dvec3 index);

using DensityHistogram = std::array<std::uint64_t, kDensityLevels>;

// Number of voxels per 12-bit density (labels ignored).
DensityHistogram densityHistogram(const Volume& volume);

// Whether the densities look like calibrated Hounsfield units: a CT of the body holds air (around
// it, in the lungs and bowel) below -500 HU, at least 0.1 % of its voxels. Exported and cropped
// research data (../shared/data/aorta.mha) often hold none.
bool looksHuCalibrated(const Volume& volume);
bool looksHuCalibrated(const DensityHistogram& histogram);  // the same from the volume's histogram

struct DensityRange {
  int minDensity = 0;
  int maxDensity = 0;
};
DensityRange densityRange(const Volume& volume);

}  // namespace angio
