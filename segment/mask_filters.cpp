#include "segment/mask_filters.h"

#include <vector>

#include <itkBinaryBallStructuringElement.h>
#include <itkBinaryDilateImageFilter.h>
#include <itkBinaryErodeImageFilter.h>
#include <itkBinaryFillholeImageFilter.h>
#include <itkBinaryImageToShapeLabelMapFilter.h>
#include <itkBinaryShapeKeepNObjectsImageFilter.h>
#include <itkBinaryShapeOpeningImageFilter.h>
#include <itkBinaryThresholdImageFilter.h>
#include <itkExtractImageFilter.h>
#include <itkImageRegionConstIteratorWithIndex.h>
#include <itkLabelMapToBinaryImageFilter.h>
#include <itkMaskNegatedImageFilter.h>

namespace angio::segment {

namespace {

using Ball = itk::BinaryBallStructuringElement<std::uint8_t, 3>;
using Mask2d = itk::Image<std::uint8_t, 2>;

// Runs the filter as one step and detaches its output, so the filter (and its input) can go.
template <class Filter>
MaskImage::Pointer result(Filter& filter, SegmentationRun& run) {
  run.update(filter);
  MaskImage::Pointer output = filter.GetOutput();
  output->DisconnectPipeline();
  return output;
}

Ball ball(int radius) {
  Ball element;
  element.SetRadius(radius);
  element.CreateStructuringElement();
  return element;
}

template <class Filter>
MaskImage::Pointer morphology(const MaskImage* mask, int radius, SegmentationRun& run) {
  auto filter = Filter::New();
  filter->SetInput(mask);
  filter->SetKernel(ball(radius));
  filter->SetForegroundValue(1);
  return result(*filter, run);
}

// Fills the 2D holes of the slice at `index` across `axis`, in place.
void fillSliceHoles(MaskImage* mask, int axis, long index) {
  MaskImage::RegionType region = mask->GetLargestPossibleRegion();
  region.SetIndex(axis, index);
  region.SetSize(axis, 0);
  auto extract = itk::ExtractImageFilter<MaskImage, Mask2d>::New();
  extract->SetInput(mask);
  extract->SetExtractionRegion(region);
  extract->SetDirectionCollapseToIdentity();
  auto fill = itk::BinaryFillholeImageFilter<Mask2d>::New();
  fill->SetInput(extract->GetOutput());
  fill->SetForegroundValue(1);
  fill->Update();
  for (itk::ImageRegionConstIteratorWithIndex<Mask2d> it(fill->GetOutput(),
                                                         fill->GetOutput()->GetLargestPossibleRegion());
       !it.IsAtEnd(); ++it) {
    if (!it.Get()) continue;
    MaskImage::IndexType at;
    at[axis] = index;
    for (int d = 0, other = 0; d < 3; ++d)
      if (d != axis) at[d] = it.GetIndex()[other++];
    mask->SetPixel(at, 1);
  }
}

}  // namespace

MaskImage::Pointer threshold(const HuImage* image, double loHu, double hiHu, SegmentationRun& run) {
  auto filter = itk::BinaryThresholdImageFilter<HuImage, MaskImage>::New();
  filter->SetInput(image);
  filter->SetLowerThreshold(short(std::clamp(loHu, -32768.0, 32767.0)));
  filter->SetUpperThreshold(short(std::clamp(hiHu, -32768.0, 32767.0)));
  filter->SetInsideValue(1);
  filter->SetOutsideValue(0);
  return result(*filter, run);
}

MaskImage::Pointer dilate(const MaskImage* mask, int radius, SegmentationRun& run) {
  return morphology<itk::BinaryDilateImageFilter<MaskImage, MaskImage, Ball>>(mask, radius, run);
}

MaskImage::Pointer erode(const MaskImage* mask, int radius, SegmentationRun& run) {
  // The border counts as foreground (ITK's default): a bone cut by the border keeps its core there.
  return morphology<itk::BinaryErodeImageFilter<MaskImage, MaskImage, Ball>>(mask, radius, run);
}

MaskImage::Pointer subtract(const MaskImage* a, const MaskImage* b, SegmentationRun& run) {
  auto filter = itk::MaskNegatedImageFilter<MaskImage, MaskImage, MaskImage>::New();
  filter->SetInput(a);
  filter->SetMaskImage(b);
  return result(*filter, run);
}

MaskImage::Pointer keepPiecesOfAtLeast(const MaskImage* mask, double minVoxels, SegmentationRun& run) {
  auto filter = itk::BinaryShapeOpeningImageFilter<MaskImage>::New();
  filter->SetInput(mask);
  filter->SetForegroundValue(1);
  filter->SetBackgroundValue(0);
  filter->SetFullyConnected(true);
  filter->SetAttribute("NumberOfPixels");
  filter->SetLambda(minVoxels);
  return result(*filter, run);
}

MaskImage::Pointer keepLargestPiece(const MaskImage* mask, SegmentationRun& run) {
  auto filter = itk::BinaryShapeKeepNObjectsImageFilter<MaskImage>::New();
  filter->SetInput(mask);
  filter->SetForegroundValue(1);
  filter->SetBackgroundValue(0);
  filter->SetFullyConnected(true);
  filter->SetAttribute("NumberOfPixels");
  filter->SetNumberOfObjects(1);
  return result(*filter, run);
}

MaskImage::Pointer keepPiecesAlongK(const MaskImage* mask, double minFraction, SegmentationRun& run) {
  auto pieces = itk::BinaryImageToShapeLabelMapFilter<MaskImage>::New();
  pieces->SetInput(mask);
  pieces->SetInputForegroundValue(1);
  pieces->SetFullyConnected(true);
  pieces->SetComputePerimeter(false);
  pieces->SetComputeFeretDiameter(false);
  run.update(*pieces);
  auto map = pieces->GetOutput();
  const double minExtent = minFraction * mask->GetLargestPossibleRegion().GetSize(2);
  std::vector<unsigned long> shortPieces;
  for (unsigned long n = 0; n < map->GetNumberOfLabelObjects(); ++n) {
    const auto* piece = map->GetNthLabelObject(n);
    if (piece->GetBoundingBox().GetSize(2) < minExtent) shortPieces.push_back(piece->GetLabel());
  }
  for (unsigned long label : shortPieces) map->RemoveLabel(label);
  using LabelMap = itk::BinaryImageToShapeLabelMapFilter<MaskImage>::OutputImageType;
  auto toMask = itk::LabelMapToBinaryImageFilter<LabelMap, MaskImage>::New();
  toMask->SetInput(map);
  toMask->SetForegroundValue(1);
  toMask->SetBackgroundValue(0);
  return result(*toMask, run);
}

MaskImage::Pointer fillHoles(MaskImage* mask, SegmentationRun& run) {
  const MaskImage::SizeType size = mask->GetLargestPossibleRegion().GetSize();
  for (int axis = 0; axis < 3; ++axis) {
    if (size[axis] < 3) continue;
    fillSliceHoles(mask, axis, 0);
    fillSliceHoles(mask, axis, long(size[axis]) - 1);
  }
  run.throwIfCancelled();
  auto filter = itk::BinaryFillholeImageFilter<MaskImage>::New();
  filter->SetInput(mask);
  filter->SetForegroundValue(1);
  filter->SetFullyConnected(false);
  return result(*filter, run);
}

}  // namespace angio::segment
