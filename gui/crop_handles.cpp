#include "gui/crop_handles.h"

#include <algorithm>

namespace angio {

std::vector<CropHandle> cropHandles(const CropBox& box,
                                    const std::function<glm::dvec2(glm::dvec3)>& project) {
  std::vector<CropHandle> handles;
  const glm::dvec3 centre = (box.minMm + box.maxMm) * 0.5;
  for (int axis = 0; axis < 3; ++axis) {
    glm::dvec3 unit(0.0);
    unit[axis] = 1;
    for (bool atMax : {false, true}) {
      glm::dvec3 faceCentre = centre;
      faceCentre[axis] = atMax ? box.maxMm[axis] : box.minMm[axis];
      const glm::dvec2 at = project(faceCentre);
      const glm::dvec2 perMm = project(faceCentre + unit) - at;
      if (glm::length(perMm) < kMinHandlePxPerMm) continue;
      handles.push_back({{axis, atMax}, at, perMm});
    }
  }
  return handles;
}

std::optional<CropHandle> handleAt(const std::vector<CropHandle>& handles, glm::dvec2 pointer,
                                   double radiusPx) {
  std::optional<CropHandle> nearest;
  double nearestPx = radiusPx;
  for (const CropHandle& handle : handles) {
    const double px = glm::length(handle.screen - pointer);
    if (px > nearestPx) continue;
    nearestPx = px;
    nearest = handle;
  }
  return nearest;
}

CropBox draggedCropBox(const CropBox& start, const CropHandle& grabbed, glm::dvec2 dragPx,
                       glm::dvec3 extentMm) {
  const glm::dvec2 perMm = grabbed.screenPerMm;
  const double mm = glm::dot(dragPx, perMm) / glm::dot(perMm, perMm);
  const int axis = grabbed.face.axis;
  CropBox box = start;
  if (grabbed.face.atMax)
    box.maxMm[axis] = std::max(std::min(start.maxMm[axis] + mm, extentMm[axis]), start.minMm[axis]);
  else box.minMm[axis] = std::min(std::max(start.minMm[axis] + mm, 0.0), start.maxMm[axis]);
  return box;
}

}  // namespace angio
