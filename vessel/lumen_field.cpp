#include "vessel/lumen_field.h"

#include <algorithm>
#include <cmath>

#include <itkImage.h>
#include <itkSignedMaurerDistanceMapImageFilter.h>
#include <tbb/parallel_for.h>

#include "core/labels.h"
#include "core/voxel.h"
#include "vessel/itk_cancel.h"

namespace angio {

namespace {

using MaskImage = itk::Image<std::uint8_t, 3>;
using DistanceImage = itk::Image<float, 3>;

// Bone and table that removal labelled are never lumen, even where marrow or a partial-volume
// shell has contrast-like density.
bool isRemovedLabel(int label) { return label == kBoneLabel || label == kTableLabel; }

bool isLumenVoxel(Voxel v, int low, int high) {
  const int d = densityOf(v);
  return d >= low && d <= high && !isRemovedLabel(labelOf(v));
}

// 1 where the box's voxel is NOT lumen: the distance map measures to these.
MaskImage::Pointer wallMask(const Volume& volume, ContrastRange range, const VoxelBox& box) {
  const glm::ivec3 size = sizeOf(box);
  auto mask = MaskImage::New();
  MaskImage::SizeType itkSize;
  for (int axis = 0; axis < 3; ++axis) itkSize[axis] = itk::SizeValueType(size[axis]);
  mask->SetRegions(MaskImage::RegionType(itkSize));
  MaskImage::SpacingType itkSpacing;
  for (int axis = 0; axis < 3; ++axis) itkSpacing[axis] = volume.spacing[axis];
  mask->SetSpacing(itkSpacing);
  mask->Allocate();
  const int low = densityOfHu(range.lowHu), high = densityOfHu(range.highHu);
  std::uint8_t* out = mask->GetBufferPointer();
  tbb::parallel_for(0, size.z, [&](int k) {
    for (int j = 0; j < size.y; ++j) {
      std::uint8_t* row = out + (std::size_t(k) * size.y + j) * size.x;
      for (int i = 0; i < size.x; ++i) {
        row[i] = isLumenVoxel(volume.at(box.lo.x + i, box.lo.y + j, box.lo.z + k), low, high) ? 0 : 1;
      }
    }
  });
  return mask;
}

// The box around the lumen voxels inside `box`, one voxel of wall added on each side where the box
// allows (the distance map needs the wall beyond the last lumen voxel); empty without lumen.
VoxelBox lumenBounds(const Volume& volume, ContrastRange range, const VoxelBox& box) {
  const int low = densityOfHu(range.lowHu), high = densityOfHu(range.highHu);
  std::vector<VoxelBox> perSlice(std::size_t(sizeOf(box).z));
  tbb::parallel_for(box.lo.z, box.hi.z + 1, [&](int k) {
    VoxelBox& slice = perSlice[std::size_t(k - box.lo.z)];
    slice.lo = glm::ivec3(box.hi.x + 1, box.hi.y + 1, k);
    slice.hi = glm::ivec3(box.lo.x - 1, box.lo.y - 1, k);
    for (int j = box.lo.y; j <= box.hi.y; ++j)
      for (int i = box.lo.x; i <= box.hi.x; ++i) {
        if (!isLumenVoxel(volume.at(i, j, k), low, high)) continue;
        slice.lo = glm::min(slice.lo, glm::ivec3(i, j, k));
        slice.hi = glm::max(slice.hi, glm::ivec3(i, j, k));
      }
  });
  VoxelBox bounds;
  bool any = false;
  for (const VoxelBox& slice : perSlice) {
    if (isEmpty(slice)) continue;
    bounds.lo = any ? glm::min(bounds.lo, slice.lo) : slice.lo;
    bounds.hi = any ? glm::max(bounds.hi, slice.hi) : slice.hi;
    any = true;
  }
  if (!any) return {};
  return {glm::max(bounds.lo - 1, box.lo), glm::min(bounds.hi + 1, box.hi)};
}

int clampedIndex(double index, int count) { return std::clamp(int(std::floor(index)), 0, count - 1); }

}  // namespace

ContrastRange contrastRangeFor(double lumenHu, double tissueHu, std::optional<double> calciumHu) {
  const double low = 0.5 * (lumenHu + tissueHu);
  return {low, calciumHu ? *calciumHu : lumenHu + 2 * (lumenHu - low)};
}

bool isEmpty(const VoxelBox& box) { return glm::any(glm::lessThan(box.hi, box.lo)); }
glm::ivec3 sizeOf(const VoxelBox& box) { return isEmpty(box) ? glm::ivec3(0) : box.hi - box.lo + 1; }
bool contains(const VoxelBox& box, glm::ivec3 voxel) {
  return glm::all(glm::greaterThanEqual(voxel, box.lo)) && glm::all(glm::lessThanEqual(voxel, box.hi));
}
VoxelBox wholeVolume(const Volume& volume) { return {glm::ivec3(0), volume.dims - 1}; }

VoxelBox boxAround(const Volume& volume, const std::vector<glm::dvec3>& pointsMm, double marginMm) {
  if (pointsMm.empty()) return {};
  glm::dvec3 lo = pointsMm.front(), hi = pointsMm.front();
  for (const glm::dvec3& p : pointsMm) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  VoxelBox box;
  for (int axis = 0; axis < 3; ++axis) {
    box.lo[axis] = clampedIndex((lo[axis] - marginMm) / volume.spacing[axis], volume.dims[axis]);
    box.hi[axis] = clampedIndex((hi[axis] + marginMm) / volume.spacing[axis] + 1, volume.dims[axis]);
  }
  return box;
}

bool containsBox(const VoxelBox& outer, const VoxelBox& inner) {
  return isEmpty(inner) || (contains(outer, inner.lo) && contains(outer, inner.hi));
}

LumenField::LumenField(const Volume& volume, ContrastRange range, VoxelBox box,
                       const std::atomic<bool>* cancel)
    : coverage_(box), spacing_(volume.spacing), range_(range) {
  if (isEmpty(box)) return;
  // Only where there is lumen: the map of a run-off's arteries and bone rims covers a fifth of the
  // volume, and Maurer's time and memory grow with the voxels.
  box_ = lumenBounds(volume, range, box);
  size_ = sizeOf(box_);
  if (isEmpty(box_)) {
    distanceMm_ = std::make_shared<const float>(0.0f);  // ready, with no lumen
    return;
  }
  // The distance from each lumen voxel to the nearest wall voxel: the wall is the object, the
  // lumen lies outside it, where Maurer's signed distance is positive.
  using Filter = itk::SignedMaurerDistanceMapImageFilter<MaskImage, DistanceImage>;
  auto filter = Filter::New();
  filter->SetInput(wallMask(volume, range, box_));
  filter->SetInsideIsPositive(false);
  filter->SetSquaredDistance(false);
  filter->SetUseImageSpacing(true);
  filter->SetBackgroundValue(0);
  if (!updateUnlessCancelled(*filter, cancel)) return;
  // The map is kept as ITK made it (no copy of a possibly 1.3 GB buffer); wall voxels become 0.
  DistanceImage::Pointer image = filter->GetOutput();
  float* distance = image->GetBufferPointer();
  count_ = std::size_t(size_.x) * size_.y * size_.z;
  tbb::parallel_for(std::size_t(0), count_, std::size_t(1) << 20, [&](std::size_t start) {
    const std::size_t end = std::min(count_, start + (std::size_t(1) << 20));
    for (std::size_t n = start; n < end; ++n) distance[n] = std::max(distance[n], 0.0f);
  });
  distanceMm_ = std::shared_ptr<const float>(distance, [image](const float*) {});
}

glm::ivec3 LumenField::voxelOf(std::size_t offset) const {
  const std::size_t row = offset / std::size_t(size_.x);
  return box_.lo + glm::ivec3(int(offset % size_.x), int(row % size_.y), int(row / size_.y));
}

}  // namespace angio
