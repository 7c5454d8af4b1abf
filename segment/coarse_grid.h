#pragma once
// The coarse grid the heavy morphology runs on: the volume shrunk by 2 along axes whose spacing is
// finer than kCoarseAboveMm (512 x 512 x 1200 at 0.8 x 0.8 x 1 mm becomes 256 x 256 x 600), as ITK
// images of one value per block of voxels. Shrinking is written here rather than with ITK's shrink
// filters: they subsample or average, and a thin cortex must survive as the block's maximum, read
// straight from the 16-bit voxels without a full-size ITK copy.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <itkImage.h>

#include "core/volume.h"
#include "segment/segmentation_run.h"

namespace angio::segment {

using MaskImage = itk::Image<std::uint8_t, 3>;  // 0 or 1
using HuImage = itk::Image<short, 3>;

inline constexpr double kCoarseAboveMm = 1.2;

struct CoarseGrid {
  glm::ivec3 factor{1};  // voxels per block along i, j, k
  glm::ivec3 dims{0};
  glm::dvec3 spacing{1.0};  // mm

  std::size_t indexOf(int i, int j, int k) const {
    return (std::size_t(k / factor.z) * dims.y + j / factor.y) * dims.x + i / factor.x;
  }
  double voxelMm3() const { return spacing.x * spacing.y * spacing.z; }
};

CoarseGrid coarseGridFor(const Volume& volume);

enum class BlockValue { maximum, mean };

// One HU per block; voxels whose `excluded` byte has excludedBit set count as air for the maximum
// (protected lumen seeds no bone). excluded may be empty.
HuImage::Pointer shrinkToBlocks(const Volume& volume, const CoarseGrid& grid, BlockValue value,
                                const std::vector<std::uint8_t>& excluded, std::uint8_t excludedBit,
                                const SegmentationRun& run);

MaskImage::Pointer makeMask(const CoarseGrid& grid);

}  // namespace angio::segment
