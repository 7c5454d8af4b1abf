#include "gui/clip_state.h"

#include <algorithm>
#include <cmath>

namespace angio {

namespace {

constexpr double kDegrees = 180 / 3.14159265358979323846;

}  // namespace

glm::dvec3 clipNormalOf(const ClipState& clip) {
  const double length = glm::length(clip.normal);
  if (!(length > 0) || !std::isfinite(length)) return {1, 0, 0};
  return clip.normal / length;
}

glm::dvec3 normalFromAngles(glm::dvec2 azimuthElevationDeg) {
  const double azimuth = azimuthElevationDeg.x / kDegrees, elevation = azimuthElevationDeg.y / kDegrees;
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
          std::sin(elevation)};
}

glm::dvec2 anglesOfNormal(glm::dvec3 normal) {
  const glm::dvec3 n = glm::normalize(normal);
  const bool alongK = std::abs(n.x) < 1e-12 && std::abs(n.y) < 1e-12;
  return {alongK ? 0 : std::atan2(n.y, n.x) * kDegrees,
          std::asin(std::clamp(n.z, -1.0, 1.0)) * kDegrees};
}

// A facing plane at depth d (away from the viewer) removes the half-space towards the viewer of
// the point centre + d * viewDir; as a fixed plane that is the normal towards the viewer and the
// offset -d along it.
ClipState fixedToView(ClipState clip, glm::dvec3 towardsViewer) {
  if (!clip.facingViewer) return clip;
  clip.facingViewer = false;
  clip.normal = glm::normalize(towardsViewer);
  clip.planeOffsetMm = 0.0 - clip.planeOffsetMm;  // (0 - x: never -0)
  return clip;
}

double planeReachMm(glm::dvec3 normal, glm::dvec3 extentMm) {
  return 0.5 * glm::dot(glm::abs(normal), extentMm);
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
