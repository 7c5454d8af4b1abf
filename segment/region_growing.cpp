#include "segment/region_growing.h"

#include <algorithm>
#include <limits>

#include <itkBinaryFillholeImageFilter.h>
#include <itkConnectedThresholdImageFilter.h>
#include <itkImageAdaptor.h>
#include <itkImageRegionConstIteratorWithIndex.h>
#include <itkImportImageFilter.h>
#include <itkProcessObject.h>
#include <itkRegionOfInterestImageFilter.h>

#include "core/voxel.h"
#include "vessel/itk_cancel.h"

namespace angio {

namespace {

using VoxelImage = itk::Image<Voxel, 3>;
using MaskImage = itk::Image<std::uint8_t, 3>;

// The volume's voxels as an ITK image, without a copy.
VoxelImage::Pointer voxelImage(const Volume& volume) {
  auto import = itk::ImportImageFilter<Voxel, 3>::New();
  itk::ImportImageFilter<Voxel, 3>::SizeType size;
  for (int axis = 0; axis < 3; ++axis) size[axis] = itk::SizeValueType(volume.dims[axis]);
  import->SetRegion(itk::ImageRegion<3>(size));
  import->SetImportPointer(const_cast<Voxel*>(volume.voxels.data()), volume.voxels.size(), false);
  import->Update();
  return import->GetOutput();
}

// What the growing sees of a voxel: its density where its label may join, else -1 (below every
// range), so other labels stop the region as air would.
class JoinableDensity {
 public:
  using InternalType = Voxel;
  using ExternalType = int;
  void SetLabel(int label) { label_ = label; }
  ExternalType Get(const InternalType& voxel) const {
    const int label = labelOf(voxel);
    return label == 0 || label == label_ ? densityOf(voxel) : -1;
  }
  bool operator!=(const JoinableDensity& other) const { return label_ != other.label_; }

 private:
  int label_ = 0;
};

// A voxel's label as the growing sees it: equal to the seed's or not.
class LabelOnly {
 public:
  using InternalType = Voxel;
  using ExternalType = int;
  ExternalType Get(const InternalType& voxel) const { return labelOf(voxel); }
  bool operator!=(const LabelOnly&) const { return false; }
};

template <class Adaptor>
MaskImage::Pointer connectedThreshold(Adaptor* image, glm::ivec3 seed, int lo, int hi,
                                      const std::atomic<bool>* cancel) {
  auto grow = itk::ConnectedThresholdImageFilter<Adaptor, MaskImage>::New();
  grow->SetInput(image);
  grow->SetLower(lo);
  grow->SetUpper(hi);
  grow->SetReplaceValue(1);
  grow->AddSeed({{seed.x, seed.y, seed.z}});
  if (!updateUnlessCancelled(*grow, cancel)) return nullptr;
  return grow->GetOutput();
}

// The mask's voxels as volume indices, and their bounding box.
struct MaskVoxels {
  std::vector<std::size_t> indices;
  glm::ivec3 lo{0}, hi{-1};
};

MaskVoxels voxelsOf(const MaskImage* mask, const itk::ImageRegion<3>& region, glm::ivec3 dims) {
  MaskVoxels found{{}, glm::ivec3(std::numeric_limits<int>::max()), glm::ivec3(-1)};
  for (itk::ImageRegionConstIteratorWithIndex<MaskImage> it(mask, region); !it.IsAtEnd(); ++it) {
    if (!it.Get()) continue;
    const auto index = it.GetIndex();
    const glm::ivec3 v{int(index[0]), int(index[1]), int(index[2])};
    found.indices.push_back((std::size_t(v.z) * dims.y + v.y) * dims.x + v.x);
    found.lo = glm::min(found.lo, v);
    found.hi = glm::max(found.hi, v);
  }
  return found;
}

bool cancelled(const std::atomic<bool>* cancel) { return cancel && cancel->load(); }

// The region with the holes it encloses in its bounding box, where those voxels may join.
std::vector<std::size_t> withHolesFilled(const Volume& volume, const MaskImage* region,
                                         const MaskVoxels& grown, int label,
                                         const std::atomic<bool>* cancel) {
  itk::ImageRegion<3> box;
  for (int axis = 0; axis < 3; ++axis) {
    box.SetIndex(axis, grown.lo[axis]);
    box.SetSize(axis, itk::SizeValueType(grown.hi[axis] - grown.lo[axis] + 1));
  }
  auto crop = itk::RegionOfInterestImageFilter<MaskImage, MaskImage>::New();
  crop->SetInput(region);
  crop->SetRegionOfInterest(box);
  auto fill = itk::BinaryFillholeImageFilter<MaskImage>::New();
  fill->SetInput(crop->GetOutput());
  fill->SetForegroundValue(1);
  fill->SetFullyConnected(false);
  if (!updateUnlessCancelled(*fill, cancel)) return {};
  const MaskImage* filled = fill->GetOutput();
  std::vector<std::size_t> indices;
  for (itk::ImageRegionConstIteratorWithIndex<MaskImage> it(filled, filled->GetLargestPossibleRegion());
       !it.IsAtEnd(); ++it) {
    if (!it.Get()) continue;
    const auto index = it.GetIndex();
    const glm::ivec3 v = grown.lo + glm::ivec3{int(index[0]), int(index[1]), int(index[2])};
    const std::size_t n = volume.indexOf(v.x, v.y, v.z);
    const int existing = labelOf(volume.voxels[n]);
    if (existing == 0 || existing == label) indices.push_back(n);
  }
  std::sort(indices.begin(), indices.end());
  return indices;
}

bool inside(const Volume& volume, glm::ivec3 v) {
  return glm::all(glm::greaterThanEqual(v, glm::ivec3(0))) && glm::all(glm::lessThan(v, volume.dims));
}

}  // namespace

std::vector<std::size_t> growRegion(const Volume& volume, glm::ivec3 seed, const GrowSettings& settings,
                                    const std::atomic<bool>* cancel) {
  if (!inside(volume, seed)) return {};
  const VoxelImage::Pointer voxels = voxelImage(volume);
  auto joinable = itk::ImageAdaptor<VoxelImage, JoinableDensity>::New();
  JoinableDensity accessor;
  accessor.SetLabel(settings.label);
  joinable->SetPixelAccessor(accessor);
  joinable->SetImage(voxels);
  const MaskImage::Pointer region = connectedThreshold(
      joinable.GetPointer(), seed, densityOfHu(settings.lowHu), densityOfHu(settings.highHu), cancel);
  if (!region || cancelled(cancel)) return {};
  const MaskVoxels grown = voxelsOf(region, region->GetLargestPossibleRegion(), volume.dims);
  if (grown.indices.empty() || !settings.fillHoles) return grown.indices;
  return withHolesFilled(volume, region, grown, settings.label, cancel);
}

std::vector<std::size_t> connectedLabelled(const Volume& volume, glm::ivec3 seed,
                                           const std::atomic<bool>* cancel) {
  if (!inside(volume, seed)) return {};
  const int label = labelOf(volume.at(seed.x, seed.y, seed.z));
  if (label == 0) return {};
  const VoxelImage::Pointer voxels = voxelImage(volume);
  auto labels = itk::ImageAdaptor<VoxelImage, LabelOnly>::New();
  labels->SetImage(voxels);
  const MaskImage::Pointer region = connectedThreshold(labels.GetPointer(), seed, label, label, cancel);
  if (!region || cancelled(cancel)) return {};
  return voxelsOf(region, region->GetLargestPossibleRegion(), volume.dims).indices;
}

}  // namespace angio
