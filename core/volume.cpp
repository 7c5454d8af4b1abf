#include "core/volume.h"

#include <numeric>

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace angio {

Volume makeVolume(glm::ivec3 dims, glm::dvec3 spacing, Voxel fill) {
  Volume volume;
  volume.dims = dims;
  volume.spacing = spacing;
  volume.voxels.assign(volume.voxelCount(), fill);
  return volume;
}

glm::dvec3 domainExtent(const Volume& volume) { return glm::dvec3(volume.dims - 1) * volume.spacing; }

double voxelUnit(const Volume& volume) {
  return std::min({volume.spacing.x, volume.spacing.y, volume.spacing.z});
}

glm::dvec3 physicalToIndex(const Volume& volume, glm::dvec3 physical) {
  return glm::inverse(volume.direction) * (physical - volume.origin) / volume.spacing;
}

glm::dvec3 indexToPhysical(const Volume& volume, glm::dvec3 index) {
  return volume.origin + volume.direction * (index * volume.spacing);
}

DensityHistogram densityHistogram(const Volume& volume) {
  const auto& voxels = volume.voxels;
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, voxels.size(), 1 << 20), DensityHistogram{},
      [&](const tbb::blocked_range<std::size_t>& range, DensityHistogram counts) {
        for (std::size_t n = range.begin(); n != range.end(); ++n) ++counts[densityOf(voxels[n])];
        return counts;
      },
      [](DensityHistogram a, const DensityHistogram& b) {
        for (int d = 0; d < kDensityLevels; ++d) a[d] += b[d];
        return a;
      });
}

DensityRange densityRange(const Volume& volume) {
  const DensityHistogram counts = densityHistogram(volume);
  DensityRange range{kDensityLevels - 1, 0};
  for (int d = 0; d < kDensityLevels; ++d) {
    if (counts[d] == 0) continue;
    range.minDensity = std::min(range.minDensity, d);
    range.maxDensity = std::max(range.maxDensity, d);
  }
  return range;
}

bool looksHuCalibrated(const Volume& volume) { return looksHuCalibrated(densityHistogram(volume)); }

bool looksHuCalibrated(const DensityHistogram& histogram) {
  const std::size_t all = std::accumulate(histogram.begin(), histogram.end(), std::size_t(0));
  const std::size_t below =
      std::accumulate(histogram.begin(), histogram.begin() + densityOfHu(-500), std::size_t(0));
  return below * 1000 >= all;
}

}  // namespace angio
