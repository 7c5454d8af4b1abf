#include "gui/slice_pane.h"

#include <algorithm>
#include <cmath>

namespace angio {

SlicePlacement placeSlice(glm::ivec2 imageSize, glm::dvec2 spacingMm, glm::dvec2 paneMin,
                          glm::dvec2 paneSize, double zoom, glm::dvec2 panPx) {
  const glm::dvec2 sizeMm = glm::dvec2(glm::max(imageSize, glm::ivec2(1))) * spacingMm;
  const double fitPerMm =
      std::max(std::min(paneSize.x / sizeMm.x, paneSize.y / sizeMm.y), 1e-6);  // fit, keep mm square
  const double screenPerMm = fitPerMm * zoom;
  SlicePlacement placement;
  placement.scale = spacingMm * screenPerMm;
  placement.size = sizeMm * screenPerMm;
  placement.min = paneMin + paneSize * 0.5 + panPx - placement.size * 0.5;
  return placement;
}

glm::dvec2 screenOfSlicePixel(const SlicePlacement& placement, glm::dvec2 pixel) {
  return placement.min + pixel * placement.scale;
}

glm::dvec2 slicePixelOfScreen(const SlicePlacement& placement, glm::dvec2 screen) {
  return (screen - placement.min) / placement.scale;
}

SliceLetters sliceLetters(SliceOrientation orientation) {
  switch (orientation) {
    case SliceOrientation::axial: return {'R', 'L', 'A', 'P'};
    case SliceOrientation::coronal: return {'R', 'L', 'S', 'I'};
    case SliceOrientation::sagittal: return {'A', 'P', 'S', 'I'};
  }
  return {'R', 'L', 'A', 'P'};
}

glm::dvec3 steppedCursor(const Volume& volume, SliceOrientation orientation, glm::dvec3 cursorMm,
                         int steps) {
  const int axis = fixedAxisOf(orientation);
  const int index = std::clamp(cursorVoxel(volume, cursorMm)[axis] + steps, 0, volume.dims[axis] - 1);
  cursorMm[axis] = index * volume.spacing[axis];
  return cursorMm;
}

WindowLevel draggedWindowLevel(WindowLevel start, glm::dvec2 dragPx) {
  return {std::max(start.window + dragPx.x * kWindowLevelHuPerPixel, 1.0),
          start.level + dragPx.y * kWindowLevelHuPerPixel};
}

}  // namespace angio
