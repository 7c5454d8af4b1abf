#include "render/slice_images.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace angio {

namespace {

// The voxel at image pixel (x, y) of a slice through `fixedIndex`.
glm::ivec3 voxelOfPixel(const Volume& volume, SliceOrientation orientation, int fixedIndex, int x,
                        int y) {
  const SliceAxes axes = axesOf(orientation);
  glm::ivec3 voxel{0};
  voxel[fixedAxisOf(orientation)] = fixedIndex;
  voxel[axes.x] = x;
  voxel[axes.y] = axes.yFlipped ? volume.dims[axes.y] - 1 - y : y;
  return voxel;
}

}  // namespace

SliceAxes axesOf(SliceOrientation orientation) {
  switch (orientation) {
    case SliceOrientation::axial: return {0, 1, false};
    case SliceOrientation::coronal: return {0, 2, true};
    case SliceOrientation::sagittal: return {1, 2, true};
  }
  return {0, 1, false};
}

const char* sliceOrientationName(SliceOrientation orientation) {
  switch (orientation) {
    case SliceOrientation::axial: return "axial";
    case SliceOrientation::coronal: return "coronal";
    case SliceOrientation::sagittal: return "sagittal";
  }
  return "axial";
}

std::uint8_t greyOfHu(double hu, WindowLevel windowLevel) {
  const double window = std::max(windowLevel.window, 1e-6);  // a zero window is a threshold
  const double f = std::clamp((hu - (windowLevel.level - window / 2)) / window, 0.0, 1.0);
  return std::uint8_t(std::lround(f * 255));
}

int fixedAxisOf(SliceOrientation orientation) {
  switch (orientation) {
    case SliceOrientation::axial: return 2;
    case SliceOrientation::coronal: return 1;
    case SliceOrientation::sagittal: return 0;
  }
  return 2;
}

glm::ivec3 cursorVoxel(const Volume& volume, glm::dvec3 pointMm) {
  glm::ivec3 voxel{0};
  for (int a = 0; a < 3; ++a)
    voxel[a] = std::clamp(int(std::lround(pointMm[a] / volume.spacing[a])), 0, volume.dims[a] - 1);
  return voxel;
}

glm::ivec2 sliceSize(const Volume& volume, SliceOrientation orientation) {
  const SliceAxes axes = axesOf(orientation);
  return {volume.dims[axes.x], volume.dims[axes.y]};
}

glm::dvec2 sliceSpacingMm(const Volume& volume, SliceOrientation orientation) {
  const SliceAxes axes = axesOf(orientation);
  return {volume.spacing[axes.x], volume.spacing[axes.y]};
}

SliceImage extractSlice(const Volume& volume, SliceOrientation orientation, glm::dvec3 cursorMm,
                        WindowLevel windowLevel) {
  if (volume.voxelCount() == 0) throw std::invalid_argument("slice of an empty volume");
  const int fixed = fixedAxisOf(orientation);
  SliceImage slice;
  slice.orientation = orientation;
  const glm::ivec2 size = sliceSize(volume, orientation);
  slice.width = size.x;
  slice.height = size.y;
  slice.index = cursorVoxel(volume, cursorMm)[fixed];
  slice.positionMm = slice.index * volume.spacing[fixed];
  slice.grey.resize(std::size_t(size.x) * size.y);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const glm::ivec3 v = voxelOfPixel(volume, orientation, slice.index, x, y);
      slice.grey[std::size_t(y) * size.x + x] =
          greyOfHu(huOfDensity(volume.densityAt(v.x, v.y, v.z)), windowLevel);
    }
  return slice;
}

glm::dvec2 slicePixelOf(const Volume& volume, SliceOrientation orientation, glm::dvec3 pointMm) {
  const SliceAxes axes = axesOf(orientation);
  const double x = pointMm[axes.x] / volume.spacing[axes.x];
  const double y = pointMm[axes.y] / volume.spacing[axes.y];
  return {x + 0.5, (axes.yFlipped ? volume.dims[axes.y] - 1 - y : y) + 0.5};
}

glm::dvec3 pointOfSlicePixel(const Volume& volume, SliceOrientation orientation, glm::dvec2 pixel,
                             glm::dvec3 cursorMm) {
  const SliceAxes axes = axesOf(orientation);
  const double y = pixel.y - 0.5;
  glm::dvec3 point = cursorMm;
  point[axes.x] = (pixel.x - 0.5) * volume.spacing[axes.x];
  point[axes.y] = (axes.yFlipped ? volume.dims[axes.y] - 1 - y : y) * volume.spacing[axes.y];
  return point;
}

glm::dvec3 clampToVolume(const Volume& volume, glm::dvec3 pointMm) {
  return glm::clamp(pointMm, glm::dvec3(0.0), domainExtent(volume));
}

std::vector<SliceCrossing> sliceCrossings(const Volume& volume, SliceOrientation orientation,
                                          glm::dvec3 cursorMm, const Centerlines& centerlines) {
  if (centerlines.frame != CenterlineFrame::volume)
    throw std::logic_error("slice crossings need centerlines in the volume frame");
  const int fixed = fixedAxisOf(orientation);
  const double plane = cursorVoxel(volume, cursorMm)[fixed] * volume.spacing[fixed];
  std::vector<SliceCrossing> crossings;
  for (std::size_t p = 0; p < centerlines.paths.size(); ++p) {
    const std::vector<CenterlinePoint>& points = centerlines.paths[p].points;
    for (std::size_t n = 1; n < points.size(); ++n) {
      const glm::dvec3 a = points[n - 1].positionMm, b = points[n].positionMm;
      if ((a[fixed] < plane) == (b[fixed] < plane)) continue;
      const double t = (plane - a[fixed]) / (b[fixed] - a[fixed]);
      crossings.push_back({int(p), slicePixelOf(volume, orientation, a + t * (b - a))});
    }
  }
  return crossings;
}

}  // namespace angio
