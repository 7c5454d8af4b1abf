#include "vessel/centerline_comparison.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace angio {

namespace {

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0;
  const std::size_t n = std::min(values.size() - 1, std::size_t(fraction * double(values.size())));
  std::nth_element(values.begin(), values.begin() + n, values.end());
  return values[n];
}

double mean(const std::vector<double>& values) {
  double sum = 0;
  for (double v : values) sum += v;
  return values.empty() ? 0 : sum / double(values.size());
}

}  // namespace

CenterlinePoint nearestOnPath(const CenterlinePath& path, glm::dvec3 point) {
  if (path.points.size() == 1) return path.points.front();
  CenterlinePoint nearest;
  double nearestMm = std::numeric_limits<double>::infinity();
  for (std::size_t n = 0; n + 1 < path.points.size(); ++n) {
    const CenterlinePoint& a = path.points[n];
    const CenterlinePoint& b = path.points[n + 1];
    const glm::dvec3 ab = b.positionMm - a.positionMm;
    const double length2 = glm::dot(ab, ab);
    const double t =
        length2 > 0 ? std::clamp(glm::dot(point - a.positionMm, ab) / length2, 0.0, 1.0) : 0.0;
    const glm::dvec3 on = a.positionMm + t * ab;
    const double mm = glm::length(point - on);
    if (mm < nearestMm) {
      nearestMm = mm;
      nearest = {on, a.radiusMm + t * (b.radiusMm - a.radiusMm)};
    }
  }
  return nearest;
}

CenterlineDeviation deviationFrom(const CenterlinePath& traced, const CenterlinePath& reference) {
  std::vector<double> distances, radiusErrors;
  for (const CenterlinePoint& point : traced.points) {
    const CenterlinePoint nearest = nearestOnPath(reference, point.positionMm);
    distances.push_back(glm::length(point.positionMm - nearest.positionMm));
    if (point.radiusMm > 0 && nearest.radiusMm > 0)
      radiusErrors.push_back(std::abs(point.radiusMm - nearest.radiusMm) / nearest.radiusMm);
  }
  CenterlineDeviation deviation;
  deviation.points = distances.size();
  deviation.meanMm = mean(distances);
  deviation.p95Mm = percentile(distances, 0.95);
  deviation.maxMm = distances.empty() ? 0 : *std::max_element(distances.begin(), distances.end());
  deviation.meanRadiusError = mean(radiusErrors);
  deviation.p95RadiusError = percentile(radiusErrors, 0.95);
  return deviation;
}

}  // namespace angio
