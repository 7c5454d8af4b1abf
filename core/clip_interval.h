#pragma once
// A ray's depth interval under the view's clipping (core/view_clipping.h): the crop box's slab
// test, the clip plane's half-space and the thick slab, intersected. For a parallel projection each
// of them keeps one interval of t (a convex set meets a line in one interval), so a ray renders the
// samples of the global grid t_k = k delta with begin <= t_k < end, and nothing else changes: both
// raycasters and the pick take the same samples from sampleRange and this.
#include <limits>
#include <string>

#include <glm/glm.hpp>

#include "core/view_clipping.h"
#include "core/view_geometry.h"

namespace angio {

// Depths t (mm along p(t) = origin + t d): begin <= t < end.
struct DepthInterval {
  double begin = -std::numeric_limits<double>::infinity();
  double end = std::numeric_limits<double>::infinity();

  bool empty() const { return !(begin < end); }
};

// The depths of the ray from `origin` (ViewGeometry::rayOrigin) that `clipping` keeps.
DepthInterval clipInterval(const ViewClipping& clipping, const ViewGeometry& view, glm::dvec3 origin);

// The ray's samples inside the domain (sampleRange) whose depth k * delta lies in the clip interval.
SampleRange clippedSampleRange(const ViewGeometry& view, const ViewClipping& clipping,
                               glm::dvec3 origin);

// A problem with the clipping as one line (a non-finite number, an empty box, a zero normal, a
// slab not thicker than 0), or "" when it can be rendered.
std::string clippingProblem(const ViewClipping& clipping);

}  // namespace angio
