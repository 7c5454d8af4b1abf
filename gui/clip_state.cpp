#include "gui/clip_state.h"

namespace angio {

glm::dvec3 clipNormalOf(const ClipState& clip) {
  glm::dvec3 normal(0.0);
  normal[int(clip.normalAxis)] = clip.flipNormal ? -1.0 : 1.0;
  return normal;
}

ViewClipping viewClippingOf(const ClipState& clip, glm::dvec3 extentMm) {
  ViewClipping clipping;
  if (clip.cropOn) clipping.crop = clip.crop;
  if (clip.planeOn && clip.facingViewer) clipping.plane = facingPlane(clip.planeOffsetMm);
  if (clip.planeOn && !clip.facingViewer) {
    const glm::dvec3 normal = clipNormalOf(clip);
    clipping.plane = ClipPlane{false, 0, extentMm * 0.5 + clip.planeOffsetMm * normal, normal};
  }
  if (clip.slabOn) clipping.slab = clip.slab;
  return clipping;
}

}  // namespace angio
