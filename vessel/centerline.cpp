#include "vessel/centerline.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace angio {

namespace {

std::string quoted(const CenterlinePath& path) { return "path '" + path.name + "'"; }

std::string countOf(std::size_t count, const char* singular, const char* plural) {
  return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

bool isFinite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Continuous voxel index of a point given in `frame`.
glm::dvec3 voxelIndexOf(const Volume& volume, CenterlineFrame frame, glm::dvec3 positionMm) {
  return frame == CenterlineFrame::physical ? physicalToIndex(volume, positionMm)
                                            : positionMm / volume.spacing;
}

bool insideVolume(const Volume& volume, glm::dvec3 index) {
  const glm::dvec3 nearest = glm::floor(index + 0.5);
  return glm::all(glm::greaterThanEqual(nearest, glm::dvec3(0.0))) &&
         glm::all(glm::lessThan(nearest, glm::dvec3(volume.dims)));
}

// The point at arc length s (0 <= s <= total), given the path's cumulative arc lengths.
// `segment` is a cursor that only moves forward, so a sweep over increasing s is linear.
CenterlinePoint pointAtArcLength(const CenterlinePath& path, const std::vector<double>& arc, double s,
                                 std::size_t& segment) {
  const std::size_t last = path.points.size() - 1;
  while (segment + 1 < last && arc[segment + 1] < s) ++segment;
  const CenterlinePoint& a = path.points[segment];
  const CenterlinePoint& b = path.points[segment + 1];
  const double length = arc[segment + 1] - arc[segment];
  const double t = length > 0 ? std::clamp((s - arc[segment]) / length, 0.0, 1.0) : 0.0;
  return {glm::mix(a.positionMm, b.positionMm, t), a.radiusMm + t * (b.radiusMm - a.radiusMm)};
}

void checkPath(const CenterlinePath& path, std::vector<CenterlineIssue>& issues) {
  const auto error = [&](const std::string& problem) {
    issues.push_back({IssueSeverity::error, quoted(path) + ": " + problem});
  };
  const auto warning = [&](const std::string& problem) {
    issues.push_back({IssueSeverity::warning, quoted(path) + ": " + problem});
  };
  if (path.points.empty()) return error("has no points");
  std::size_t zeroRadii = 0;
  for (std::size_t n = 0; n < path.points.size(); ++n) {
    const CenterlinePoint& point = path.points[n];
    const std::string where = "point " + std::to_string(n) + ": ";
    if (!isFinite(point.positionMm)) return error(where + "coordinate is not finite");
    if (!std::isfinite(point.radiusMm)) return error(where + "radius is not finite");
    if (point.radiusMm < 0) return error(where + "negative radius");
    zeroRadii += point.radiusMm == 0;
  }
  if (path.points.size() == 1) warning("has a single point");
  if (zeroRadii > 0) {
    warning(std::to_string(zeroRadii) + " of " +
            countOf(path.points.size(), "point has", "points have") + " radius 0 (unknown)");
  }
}

}  // namespace

glm::dvec3 volumeFrameMm(const Volume& volume, glm::dvec3 physicalMm) {
  return physicalToIndex(volume, physicalMm) * volume.spacing;
}

glm::ivec3 nearestVoxelToPoint(const Volume& volume, glm::dvec3 physicalMm) {
  return glm::ivec3(glm::floor(physicalToIndex(volume, physicalMm) + 0.5));
}

Centerlines toVolumeFrame(const Centerlines& centerlines, const Volume& volume) {
  if (centerlines.frame != CenterlineFrame::physical) {
    throw std::logic_error("centerlines of " + centerlines.source + " are already in the volume frame");
  }
  Centerlines mapped = centerlines;
  mapped.frame = CenterlineFrame::volume;
  for (CenterlinePath& path : mapped.paths) {
    for (CenterlinePoint& point : path.points) {
      point.positionMm = volumeFrameMm(volume, point.positionMm);
    }
  }
  return mapped;
}

glm::dvec3 physicalFrameMm(const Volume& volume, glm::dvec3 volumeMm) {
  return indexToPhysical(volume, volumeMm / volume.spacing);
}

Centerlines toPhysicalFrame(const Centerlines& centerlines, const Volume& volume) {
  if (centerlines.frame != CenterlineFrame::volume) {
    throw std::logic_error("centerlines of " + centerlines.source +
                           " are already in the physical frame");
  }
  Centerlines mapped = centerlines;
  mapped.frame = CenterlineFrame::physical;
  for (CenterlinePath& path : mapped.paths) {
    for (CenterlinePoint& point : path.points)
      point.positionMm = physicalFrameMm(volume, point.positionMm);
  }
  return mapped;
}

std::vector<double> arcLengthsMm(const CenterlinePath& path) {
  std::vector<double> arc(path.points.size(), 0.0);
  for (std::size_t n = 1; n < path.points.size(); ++n) {
    arc[n] = arc[n - 1] + glm::distance(path.points[n - 1].positionMm, path.points[n].positionMm);
  }
  return arc;
}

double pathLengthMm(const CenterlinePath& path) {
  const std::vector<double> arc = arcLengthsMm(path);
  return arc.empty() ? 0.0 : arc.back();
}

CenterlinePath resampleByArcLength(const CenterlinePath& path, double stepMm) {
  if (!std::isfinite(stepMm) || stepMm <= 0) {
    throw std::invalid_argument("resampling step must be a finite length > 0 mm");
  }
  const std::vector<double> arc = arcLengthsMm(path);
  if (path.points.size() < 2 || !(arc.back() > 0)) return path;
  const double total = arc.back();
  // A sample closer than this to the end would duplicate the last point.
  const double endTolerance = 1e-9 * total;
  CenterlinePath resampled{path.name, {}};
  resampled.points.reserve(std::size_t(total / stepMm) + 2);
  std::size_t segment = 0;
  for (std::size_t k = 0;; ++k) {
    const double s = double(k) * stepMm;
    if (s >= total - endTolerance) break;
    resampled.points.push_back(pointAtArcLength(path, arc, s, segment));
  }
  resampled.points.push_back(path.points.back());
  return resampled;
}

Centerlines resampleByArcLength(const Centerlines& centerlines, double stepMm) {
  Centerlines resampled = centerlines;
  for (CenterlinePath& path : resampled.paths) path = resampleByArcLength(path, stepMm);
  return resampled;
}

BoxMm pathBounds(const CenterlinePath& path) {
  constexpr double kHuge = std::numeric_limits<double>::max();
  BoxMm box{glm::dvec3(kHuge), glm::dvec3(-kHuge)};
  double maxRadius = 0;
  for (const CenterlinePoint& point : path.points) {
    box.lo = glm::min(box.lo, point.positionMm);
    box.hi = glm::max(box.hi, point.positionMm);
    maxRadius = std::max(maxRadius, point.radiusMm);
  }
  if (!path.points.empty()) {
    box.lo -= maxRadius;
    box.hi += maxRadius;
  }
  return box;
}

std::vector<BoxMm> pathBounds(const Centerlines& centerlines) {
  std::vector<BoxMm> boxes;
  boxes.reserve(centerlines.paths.size());
  for (const CenterlinePath& path : centerlines.paths) boxes.push_back(pathBounds(path));
  return boxes;
}

std::size_t sharedPrefixLength(const CenterlinePath& a, const CenterlinePath& b, double toleranceMm) {
  const std::size_t count = std::min(a.points.size(), b.points.size());
  std::size_t n = 0;
  while (n < count && glm::distance(a.points[n].positionMm, b.points[n].positionMm) <= toleranceMm) {
    ++n;
  }
  return n;
}

std::vector<CenterlineIssue> validateCenterlines(const Centerlines& centerlines) {
  std::vector<CenterlineIssue> issues;
  if (centerlines.paths.empty()) {
    issues.push_back({IssueSeverity::error, "contains no centerline paths"});
  }
  for (const CenterlinePath& path : centerlines.paths) checkPath(path, issues);
  return issues;
}

std::vector<CenterlineIssue> checkInsideVolume(const Centerlines& centerlines, const Volume& volume) {
  std::vector<CenterlineIssue> issues;
  for (const CenterlinePath& path : centerlines.paths) {
    std::size_t outside = 0;
    for (const CenterlinePoint& point : path.points) {
      outside += !insideVolume(volume, voxelIndexOf(volume, centerlines.frame, point.positionMm));
    }
    if (outside == 0) continue;
    issues.push_back(
        {IssueSeverity::warning, quoted(path) + ": " + std::to_string(outside) + " of " +
                                     countOf(path.points.size(), "point lies", "points lie") +
                                     " outside the volume"});
  }
  return issues;
}

bool hasError(const std::vector<CenterlineIssue>& issues) {
  return std::any_of(issues.begin(), issues.end(), [](const CenterlineIssue& issue) {
    return issue.severity == IssueSeverity::error;
  });
}

std::string describe(const Centerlines& centerlines, const CenterlineIssue& issue) {
  return centerlines.source + ": " + issue.problem;
}

}  // namespace angio
