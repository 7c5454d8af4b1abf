#include "vessel/trunk_sharing.h"

#include <algorithm>

#include "vessel/centerline_comparison.h"

namespace angio {

namespace {

// How many leading points of `path` lie along `other`.
std::size_t pointsAlong(const CenterlinePath& path, const CenterlinePath& other) {
  std::size_t n = 0;
  for (; n < path.points.size(); ++n) {
    const CenterlinePoint& p = path.points[n];
    const double tolerance = std::max(0.5, 0.25 * p.radiusMm);
    if (glm::distance(nearestOnPath(other, p.positionMm).positionMm, p.positionMm) > tolerance) break;
  }
  return n;
}

std::size_t nearestPointIndex(const CenterlinePath& path, glm::dvec3 point) {
  std::size_t nearest = 0;
  for (std::size_t n = 1; n < path.points.size(); ++n)
    if (glm::distance(path.points[n].positionMm, point) <
        glm::distance(path.points[nearest].positionMm, point))
      nearest = n;
  return nearest;
}

}  // namespace

void shareTrunk(CenterlinePath& path, const std::vector<CenterlinePath>& earlier) {
  const CenterlinePath* trunk = nullptr;
  std::size_t along = 0;
  for (const CenterlinePath& other : earlier) {
    if (other.points.size() < 2) continue;
    const std::size_t n = pointsAlong(path, other);
    if (n > along) {
      along = n;
      trunk = &other;
    }
  }
  if (!trunk || along < 2) return;
  const CenterlinePoint& parting = path.points[along - 1];
  const std::size_t partingOnTrunk = nearestPointIndex(*trunk, parting.positionMm);
  const std::vector<double> arc = arcLengthsMm(*trunk);
  const double keepToMm = arc[partingOnTrunk] - 2 * parting.radiusMm;
  if (keepToMm <= 0) return;
  std::size_t keep = 0;  // the last trunk point taken
  while (keep + 1 < trunk->points.size() && arc[keep + 1] <= keepToMm) ++keep;
  const std::size_t resume = nearestPointIndex(path, trunk->points[keep].positionMm) + 1;
  std::vector<CenterlinePoint> joined(trunk->points.begin(),
                                      trunk->points.begin() + std::ptrdiff_t(keep) + 1);
  if (resume < path.points.size())
    joined.insert(joined.end(), path.points.begin() + std::ptrdiff_t(resume), path.points.end());
  path.points = std::move(joined);
}

}  // namespace angio
