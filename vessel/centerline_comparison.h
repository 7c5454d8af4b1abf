#pragma once
// How far a traced centerline lies from a reference one (the phantom's ground truth, or vmtk's):
// for each traced point the distance to the reference polyline and its radius against the
// reference radius there. Both paths in the same frame.
#include <vector>

#include "vessel/centerline.h"

namespace angio {

struct CenterlineDeviation {
  std::size_t points = 0;
  double meanMm = 0, p95Mm = 0, maxMm = 0;
  // |traced - reference| / reference over the points where both radii are known.
  double meanRadiusError = 0, p95RadiusError = 0;
};

CenterlineDeviation deviationFrom(const CenterlinePath& traced, const CenterlinePath& reference);

// The point of a polyline nearest to `point`, with the radius interpolated there.
CenterlinePoint nearestOnPath(const CenterlinePath& path, glm::dvec3 point);

}  // namespace angio
