#include "vessel/lumen_section.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <tbb/parallel_for.h>

#include "core/volume_sampling.h"

namespace angio {

namespace {

constexpr int kRayCount = 32;
constexpr int kCentringPasses = 4;
constexpr double kRayStepMm = 0.1;
constexpr double kBeyondWallMm = 2.5;  // how far past the wall "what lies beyond" is looked for

float densityAtMm(const Volume& volume, glm::dvec3 pointMm) {
  return trilinearDensity(volume, cellAt(volume, pointMm / volume.spacing));
}

// Two unit vectors spanning the plane perpendicular to `tangent`.
std::pair<glm::dvec3, glm::dvec3> planeAxes(glm::dvec3 tangent) {
  const glm::dvec3 t = glm::normalize(tangent);
  const glm::dvec3 helper = std::abs(t.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(t, helper));
  return {u, glm::cross(t, u)};
}

// Where along a ray's density profile (samples kRayStepMm apart from the centre) the wall lies:
// the first crossing of the level half way between the lumen and the first density beyond the
// range. None if the profile stays in the range.
std::optional<double> wallAlongProfile(const std::vector<float>& profile, float low, float high) {
  const float lumen = profile.front();
  std::size_t leaves = 0;
  while (leaves < profile.size() && profile[leaves] >= low && profile[leaves] <= high) ++leaves;
  if (leaves == 0 || leaves == profile.size()) return std::nullopt;
  const bool rises = profile[leaves] > high;
  const std::size_t beyondEnd =
      std::min(profile.size(), leaves + std::size_t(kBeyondWallMm / kRayStepMm));
  float beyond = profile[leaves];
  for (std::size_t m = leaves; m < beyondEnd; ++m)
    beyond = rises ? std::max(beyond, profile[m]) : std::min(beyond, profile[m]);
  const float level = 0.5f * (lumen + beyond);
  for (std::size_t m = 1; m < beyondEnd; ++m) {
    const bool crossed = rises ? profile[m] > level : profile[m] < level;
    if (!crossed) continue;
    const float a = profile[m - 1], b = profile[m];
    const double t = a == b ? 0.0 : double(a - level) / double(a - b);
    return kRayStepMm * (double(m - 1) + std::clamp(t, 0.0, 1.0));
  }
  return std::nullopt;
}

struct RayWalls {
  std::array<double, kRayCount> distanceMm{};
  std::array<bool, kRayCount> found{};
  int foundCount = 0;
};

RayWalls castRays(const Volume& volume, glm::dvec3 centre, glm::dvec3 u, glm::dvec3 v, float low,
                  float high, double searchRadiusMm) {
  RayWalls walls;
  const std::size_t samples = std::size_t(searchRadiusMm / kRayStepMm) + 1;
  std::vector<float> profile(samples);
  for (int r = 0; r < kRayCount; ++r) {
    const double angle = 2 * std::numbers::pi * r / kRayCount;
    const glm::dvec3 direction = std::cos(angle) * u + std::sin(angle) * v;
    for (std::size_t m = 0; m < samples; ++m)
      profile[m] = densityAtMm(volume, centre + double(m) * kRayStepMm * direction);
    if (const auto wall = wallAlongProfile(profile, low, high)) {
      walls.distanceMm[r] = *wall;
      walls.found[r] = true;
      ++walls.foundCount;
    }
  }
  return walls;
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// The polygon of wall points (rays without a wall, or reaching much further than the others into
// a branch or a neighbour, count at the median distance): its centroid offset in (u, v) and area.
std::pair<glm::dvec2, double> wallPolygon(const RayWalls& walls) {
  std::vector<double> found;
  for (int r = 0; r < kRayCount; ++r)
    if (walls.found[r]) found.push_back(walls.distanceMm[r]);
  const double typical = median(found);
  std::array<glm::dvec2, kRayCount> corners;
  for (int r = 0; r < kRayCount; ++r) {
    const double distance = walls.found[r] ? std::min(walls.distanceMm[r], 1.5 * typical) : typical;
    const double angle = 2 * std::numbers::pi * r / kRayCount;
    corners[r] = distance * glm::dvec2(std::cos(angle), std::sin(angle));
  }
  double area2 = 0;
  glm::dvec2 centroid6(0.0);
  for (int r = 0; r < kRayCount; ++r) {
    const glm::dvec2 a = corners[r], b = corners[(r + 1) % kRayCount];
    const double cross = a.x * b.y - b.x * a.y;
    area2 += cross;
    centroid6 += (a + b) * cross;
  }
  if (area2 <= 0) return {glm::dvec2(0.0), 0.0};
  return {centroid6 / (3.0 * area2), 0.5 * area2};
}

// A smoothed copy: each point the mean of those within halfWindow[n] points (fewer near the ends,
// symmetric, so the ends stay where they are).
std::vector<glm::dvec3> movingAverage(const std::vector<glm::dvec3>& points,
                                      const std::vector<int>& halfWindow) {
  std::vector<glm::dvec3> smoothed(points.size());
  const int last = int(points.size()) - 1;
  for (int n = 0; n <= last; ++n) {
    const int h = std::min({halfWindow[n], n, last - n});
    glm::dvec3 sum(0.0);
    for (int m = n - h; m <= n + h; ++m) sum += points[m];
    smoothed[n] = sum / double(2 * h + 1);
  }
  return smoothed;
}

std::vector<double> movingAverage(const std::vector<double>& values, int halfWindow) {
  std::vector<double> smoothed(values.size());
  const int last = int(values.size()) - 1;
  for (int n = 0; n <= last; ++n) {
    const int from = std::max(0, n - halfWindow), to = std::min(last, n + halfWindow);
    double sum = 0;
    for (int m = from; m <= to; ++m) sum += values[m];
    smoothed[n] = sum / double(to - from + 1);
  }
  return smoothed;
}

std::vector<glm::dvec3> positionsOf(const CenterlinePath& path) {
  std::vector<glm::dvec3> positions;
  for (const CenterlinePoint& p : path.points) positions.push_back(p.positionMm);
  return positions;
}

glm::dvec3 tangentAt(const std::vector<glm::dvec3>& points, int n, int halfSpan) {
  const int last = int(points.size()) - 1;
  const glm::dvec3 d = points[std::min(last, n + halfSpan)] - points[std::max(0, n - halfSpan)];
  return glm::length(d) > 0 ? d : glm::dvec3(0, 0, 1);
}

}  // namespace

std::optional<LumenSection> lumenSection(const Volume& volume, ContrastRange range, glm::dvec3 pointMm,
                                         glm::dvec3 tangent, double searchRadiusMm) {
  const float low = float(densityOfHu(range.lowHu)), high = float(densityOfHu(range.highHu));
  const auto [u, v] = planeAxes(tangent);
  std::optional<LumenSection> section;
  glm::dvec3 centre = pointMm;
  for (int pass = 0; pass < kCentringPasses; ++pass) {
    const float here = densityAtMm(volume, centre);
    if (here < low || here > high) break;
    const RayWalls walls = castRays(volume, centre, u, v, low, high, searchRadiusMm);
    if (2 * walls.foundCount < kRayCount) break;
    const auto [offset, area] = wallPolygon(walls);
    if (area <= 0) break;
    section = LumenSection{centre, std::sqrt(area / std::numbers::pi)};
    // Never further than the radius: the centroid of a section cut by a branch can lie outside.
    const glm::dvec2 step = glm::length(offset) > section->radiusMm
                                ? offset * (section->radiusMm / glm::length(offset))
                                : offset;
    centre += step.x * u + step.y * v;
    if (glm::length(step) < 0.02) break;
  }
  return section;
}

CenterlinePath centerlineFromVoxels(const Volume& volume, ContrastRange range,
                                    const std::vector<glm::ivec3>& voxels,
                                    const std::vector<float>& wallMm, double stepMm) {
  CenterlinePath raw;
  for (std::size_t n = 0; n < voxels.size(); ++n)
    raw.points.push_back({glm::dvec3(voxels[n]) * volume.spacing, double(wallMm[n])});
  if (raw.points.size() < 2) return raw;
  CenterlinePath path = resampleByArcLength(raw, stepMm);
  // Smooth the voxel staircase over about the radius (at least 1.5 mm) before taking tangents.
  std::vector<int> halfWindow;
  for (const CenterlinePoint& p : path.points)
    halfWindow.push_back(int(std::lround(std::clamp(p.radiusMm, 1.5, 5.0) / stepMm)));
  const std::vector<glm::dvec3> smooth = movingAverage(positionsOf(path), halfWindow);
  const int tangentSpan = std::max(1, int(std::lround(2.0 / stepMm)));
  std::vector<std::optional<LumenSection>> sections(smooth.size());
  tbb::parallel_for(0, int(smooth.size()), [&](int n) {
    const double search = std::max(3.0, 3.0 * path.points[n].radiusMm);
    sections[n] = lumenSection(volume, range, smooth[n], tangentAt(smooth, n, tangentSpan), search);
  });
  std::vector<glm::dvec3> centres(smooth.size());
  std::vector<double> radii(smooth.size(), -1.0);
  for (std::size_t n = 0; n < smooth.size(); ++n) {
    centres[n] = sections[n] ? sections[n]->centreMm : smooth[n];
    if (sections[n]) radii[n] = sections[n]->radiusMm;
  }
  // A failed section takes the radius of the nearest one that worked (else the distance map's).
  for (std::size_t n = 0; n < radii.size(); ++n) {
    if (radii[n] >= 0) continue;
    double best = path.points[n].radiusMm;
    for (std::size_t d = 1; d < radii.size(); ++d) {
      if (n >= d && radii[n - d] >= 0) {
        best = radii[n - d];
        break;
      }
      if (n + d < radii.size() && radii[n + d] >= 0) {
        best = radii[n + d];
        break;
      }
    }
    radii[n] = best;
  }
  const int lightly = std::max(1, int(std::lround(1.0 / stepMm)));
  const std::vector<glm::dvec3> centred =
      movingAverage(centres, std::vector<int>(centres.size(), lightly));
  const std::vector<double> smoothRadii = movingAverage(radii, lightly);
  CenterlinePath result;
  for (std::size_t n = 0; n < centred.size(); ++n) result.points.push_back({centred[n], smoothRadii[n]});
  return resampleByArcLength(result, stepMm);
}

}  // namespace angio
