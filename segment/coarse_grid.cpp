#include "segment/coarse_grid.h"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace angio::segment {

namespace {

template <class Image>
typename Image::Pointer allocate(const CoarseGrid& grid) {
  typename Image::RegionType region;
  typename Image::SpacingType spacing;
  for (int axis = 0; axis < 3; ++axis) {
    region.SetSize(axis, grid.dims[axis]);
    spacing[axis] = grid.spacing[axis];
  }
  auto image = Image::New();
  image->SetRegions(region);
  image->SetSpacing(spacing);
  image->Allocate();
  return image;
}

}  // namespace

CoarseGrid coarseGridFor(const Volume& volume) {
  CoarseGrid grid;
  for (int axis = 0; axis < 3; ++axis) {
    grid.factor[axis] = volume.spacing[axis] < kCoarseAboveMm && volume.dims[axis] > 1 ? 2 : 1;
    grid.dims[axis] = (volume.dims[axis] + grid.factor[axis] - 1) / grid.factor[axis];
    grid.spacing[axis] = volume.spacing[axis] * grid.factor[axis];
  }
  return grid;
}

MaskImage::Pointer makeMask(const CoarseGrid& grid) {
  MaskImage::Pointer mask = allocate<MaskImage>(grid);
  mask->FillBuffer(0);
  return mask;
}

HuImage::Pointer shrinkToBlocks(const Volume& volume, const CoarseGrid& grid, BlockValue value,
                                const std::vector<std::uint8_t>& excluded, std::uint8_t excludedBit,
                                const SegmentationRun& run) {
  HuImage::Pointer image = allocate<HuImage>(grid);
  short* out = image->GetBufferPointer();
  const glm::ivec3 f = grid.factor;
  tbb::parallel_for(tbb::blocked_range<int>(0, grid.dims.z), [&](const tbb::blocked_range<int>& slices) {
    for (int kc = slices.begin(); kc != slices.end(); ++kc) {
      run.throwIfCancelled();
      for (int jc = 0; jc < grid.dims.y; ++jc) {
        for (int ic = 0; ic < grid.dims.x; ++ic) {
          int maximum = 0, sum = 0, count = 0;
          for (int k = kc * f.z; k < std::min(volume.dims.z, (kc + 1) * f.z); ++k)
            for (int j = jc * f.y; j < std::min(volume.dims.y, (jc + 1) * f.y); ++j)
              for (int i = ic * f.x; i < std::min(volume.dims.x, (ic + 1) * f.x); ++i) {
                const std::size_t n = volume.indexOf(i, j, k);
                const int density = densityOf(volume.voxels[n]);
                sum += density;
                ++count;
                if (excluded.empty() || !(excluded[n] & excludedBit))
                  maximum = std::max(maximum, density);
              }
          const int density = value == BlockValue::maximum ? maximum : sum / count;
          out[(std::size_t(kc) * grid.dims.y + jc) * grid.dims.x + ic] = short(density - kHuOffset);
        }
      }
    }
  });
  return image;
}

}  // namespace angio::segment
