#pragma once
// The vessel's cross-section at a point of its centerline: the volume sampled on the plane
// through the point normal to the centerline's tangent (the "perpendicular view" a reader checks
// a stenosis on beside the CPR, thesis sec. 5.2.2). Pure sampling; the CPR pane shows it as an
// inset at its cursor.
#include <vector>

#include <glm/glm.hpp>

#include "core/volume.h"
#include "vessel/centerline.h"

namespace angio {

// size x size pixels of pixelMm, row-major; pixel (x, y) shows
// centreMm + (x - c) * pixelMm * uAxis - (y - c) * pixelMm * vAxis with c = (size - 1) / 2, so
// the centre pixel is the centerline point and image up is vAxis. NaN outside the volume.
struct CrossSection {
  int size = 0;
  double pixelMm = 0;
  glm::dvec3 centreMm{0.0};                   // volume frame
  glm::dvec3 uAxis{1, 0, 0}, vAxis{0, 1, 0};  // unit, orthogonal to the tangent and each other
  std::vector<float> hu;

  float huAt(int x, int y) const { return hu[std::size_t(y) * size + x]; }
};

// The section through centreMm (volume frame) normal to `tangent` (any length > 0), extentMm wide
// at about pixelMm (an odd pixel count, so the centre is a pixel), trilinear. `upHint` picks the
// in-plane orientation: vAxis is upHint made orthogonal to the tangent (any other axis if parallel).
CrossSection sampleCrossSection(const Volume& volume, glm::dvec3 centreMm, glm::dvec3 tangent,
                                glm::dvec3 upHint, double extentMm, double pixelMm);

// The point of `path` at arc length arcMm (clamped to the path) and the path's direction there,
// the chord over kTangentSpanMm about it: smoother than one segment of a traced, stair-stepped path.
struct PathPlace {
  glm::dvec3 pointMm{0.0};
  glm::dvec3 tangent{0, 0, 1};  // unit
};
constexpr double kTangentSpanMm = 4;
PathPlace placeOnPath(const CenterlinePath& path, double arcMm);  // path: at least 2 points

}  // namespace angio
