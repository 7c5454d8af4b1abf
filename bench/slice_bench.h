#pragma once
// Timing of the linked slice view's images (render/slice_images.h): each orientation's slice
// extracted and windowed N times, one voxel further along its fixed axis each time (as the wheel
// steps), report median, min and max. What the window adds (the display levels, the upload) is
// not in it.
#include <string>
#include <vector>

#include "core/volume.h"
#include "render/slice_images.h"

namespace angio {

struct SliceBenchRow {
  SliceOrientation orientation = SliceOrientation::axial;
  int width = 0, height = 0;
  int runs = 0;
  double medianMs = 0, minMs = 0, maxMs = 0;
};

std::vector<SliceBenchRow> runSliceBench(const Volume& volume, int runs);

std::string formatSliceBench(const std::vector<SliceBenchRow>& rows);

}  // namespace angio
