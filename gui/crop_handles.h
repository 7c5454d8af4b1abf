#pragma once
// The crop box's handles in the 3-D view: one at the centre of each of its six faces, dragged
// along the face's axis. Screen geometry only (the projection comes in as a function), so the
// panels and the tests share it without a window.
#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/view_clipping.h"

namespace angio {

// A face of the box: the plane at its minimum or maximum along a voxel axis.
struct CropFace {
  int axis = 0;
  bool atMax = false;
  friend bool operator==(const CropFace&, const CropFace&) = default;
};

struct CropHandle {
  CropFace face;
  glm::dvec2 screen{0.0};       // the face centre on screen (pixels)
  glm::dvec2 screenPerMm{0.0};  // how far the face centre moves on screen per mm along its axis
  friend bool operator==(const CropHandle&, const CropHandle&) = default;
};

// A drag of a handle: the handle and the box when it was grabbed, and where the pointer was.
struct CropGrab {
  CropHandle handle;
  CropBox start;
  glm::dvec2 pointerAtGrab{0.0};
  friend bool operator==(const CropGrab&, const CropGrab&) = default;
};

// Below this the axis points (nearly) at the viewer: a drag could not move its faces sensibly
// and their handles would sit on the box's other handles, so they are not offered.
inline constexpr double kMinHandlePxPerMm = 0.2;

// The handles of the faces that can be dragged in this view; `project` maps volume-frame mm to
// screen pixels (parallel projection: affine).
std::vector<CropHandle> cropHandles(const CropBox& box,
                                    const std::function<glm::dvec2(glm::dvec3)>& project);

// The handle within `radiusPx` of `pointer`, the nearest if several are.
std::optional<CropHandle> handleAt(const std::vector<CropHandle>& handles, glm::dvec2 pointer,
                                   double radiusPx);

// `start` with the face moved by a pointer motion of `dragPx` since the grab: the motion's part
// along the face's screen direction, in mm; kept inside [0, extent] and no farther than the
// opposite face.
CropBox draggedCropBox(const CropBox& start, const CropHandle& grabbed, glm::dvec2 dragPx,
                       glm::dvec3 extentMm);

}  // namespace angio
