#pragma once
// The ITK filters the segmentation is made of, on coarse masks (segment/coarse_grid.h), each one
// step of a SegmentationRun (progress, cancel). Radii are in coarse voxels; balls are the
// structuring elements.
#include "segment/coarse_grid.h"
#include "segment/segmentation_run.h"

namespace angio::segment {

// 1 where loHu <= value <= hiHu.
MaskImage::Pointer threshold(const HuImage* image, double loHu, double hiHu, SegmentationRun& run);

MaskImage::Pointer dilate(const MaskImage* mask, int radius, SegmentationRun& run);
MaskImage::Pointer erode(const MaskImage* mask, int radius, SegmentationRun& run);

// a and not b.
MaskImage::Pointer subtract(const MaskImage* a, const MaskImage* b, SegmentationRun& run);

// Connected pieces (26-neighbourhood) of at least minVoxels; only the largest one.
MaskImage::Pointer keepPiecesOfAtLeast(const MaskImage* mask, double minVoxels, SegmentationRun& run);
MaskImage::Pointer keepLargestPiece(const MaskImage* mask, SegmentationRun& run);
// Pieces whose extent along k is at least minFraction of the image's.
MaskImage::Pointer keepPiecesAlongK(const MaskImage* mask, double minFraction, SegmentationRun& run);

// Fills the holes: background not connected to the image's border (through faces). A solid cut by
// the border (a vertebra at the top slice) is closed there first: the holes of mask's six border
// slices are filled in place.
MaskImage::Pointer fillHoles(MaskImage* mask, SegmentationRun& run);

}  // namespace angio::segment
