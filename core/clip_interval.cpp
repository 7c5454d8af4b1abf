#include "core/clip_interval.h"

#include <algorithm>
#include <cmath>

namespace angio {

namespace {

// Below this a ray runs parallel to a face (as in sampleRange's slab test).
constexpr double kParallel = 1e-12;

void keepNoneIf(bool outside, DepthInterval& interval) {
  if (outside) interval = {0, 0};
}

// The crop box's slab test, axis by axis (closed box: a sample on a face is inside, up to the
// half-open end of the interval).
void cropTo(const CropBox& box, const ViewGeometry& view, glm::dvec3 origin, DepthInterval& interval) {
  for (int axis = 0; axis < 3; ++axis) {
    const double o = origin[axis], d = view.viewDir[axis];
    if (std::abs(d) < kParallel) {
      keepNoneIf(o < box.minMm[axis] || o > box.maxMm[axis], interval);
      continue;
    }
    double t0 = (box.minMm[axis] - o) / d, t1 = (box.maxMm[axis] - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    interval.begin = std::max(interval.begin, t0);
    interval.end = std::min(interval.end, t1);
  }
}

// Keeps n . (p(t) - point) <= 0: the side away from the normal.
void clipTo(const ClipPlane& plane, const ViewGeometry& view, glm::dvec3 origin,
            DepthInterval& interval) {
  if (plane.facingViewer) {  // normal -d through P0 + offset d: keeps t >= offset
    interval.begin = std::max(interval.begin, plane.offsetMm);
    return;
  }
  const double side = glm::dot(plane.normal, origin - plane.pointMm);
  const double along = glm::dot(plane.normal, view.viewDir);
  if (std::abs(along) < kParallel) {
    keepNoneIf(side > 0, interval);
    return;
  }
  const double t = -side / along;
  if (along > 0) interval.end = std::min(interval.end, t);
  else interval.begin = std::max(interval.begin, t);
}

// Ray origins lie in the plane through P0 perpendicular to d, so a depth from the centre is t.
void slabTo(const ThickSlab& slab, DepthInterval& interval) {
  interval.begin = std::max(interval.begin, slab.offsetMm - slab.thicknessMm / 2);
  interval.end = std::min(interval.end, slab.offsetMm + slab.thicknessMm / 2);
}

// The first k with k * delta >= t, computed as the raycasters compute depths (double(k) * delta),
// so the comparison the rendering model states holds bit for bit.
long firstSampleAtOrAfter(double t, double delta) {
  long k = long(std::ceil(t / delta));
  while (double(k) * delta < t) ++k;
  while (double(k - 1) * delta >= t) --k;
  return k;
}

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

DepthInterval clipInterval(const ViewClipping& clipping, const ViewGeometry& view, glm::dvec3 origin) {
  DepthInterval interval;
  if (clipping.crop) cropTo(*clipping.crop, view, origin, interval);
  if (clipping.plane) clipTo(*clipping.plane, view, origin, interval);
  if (clipping.slab) slabTo(*clipping.slab, interval);
  return interval;
}

SampleRange clippedSampleRange(const ViewGeometry& view, const ViewClipping& clipping,
                               glm::dvec3 origin) {
  SampleRange range = sampleRange(view, origin);
  if (!clipping.any() || range.empty()) return range;
  const DepthInterval interval = clipInterval(clipping, view, origin);
  if (interval.empty()) return {};
  // Depths beyond the domain's samples need no exact first sample: the domain bounds them.
  const double delta = view.sampleMm;
  if (interval.begin > double(range.last) * delta || interval.end <= double(range.first) * delta)
    return {};
  if (interval.begin > double(range.first) * delta)
    range.first = firstSampleAtOrAfter(interval.begin, delta);
  if (interval.end <= double(range.last) * delta)
    range.last = firstSampleAtOrAfter(interval.end, delta) - 1;
  return range.empty() ? SampleRange{} : range;
}

std::string clippingProblem(const ViewClipping& clipping) {
  if (const auto& crop = clipping.crop) {
    if (!finite(crop->minMm) || !finite(crop->maxMm)) return "the crop box has a non-finite bound";
    for (int axis = 0; axis < 3; ++axis)
      if (crop->minMm[axis] > crop->maxMm[axis])
        return std::string("the crop box's ") + "ijk"[axis] + " minimum exceeds its maximum";
  }
  if (const auto& plane = clipping.plane) {
    if (!std::isfinite(plane->offsetMm) || !finite(plane->pointMm) || !finite(plane->normal))
      return "the clip plane has a non-finite number";
    if (!plane->facingViewer && glm::dot(plane->normal, plane->normal) == 0)
      return "the clip plane's normal is zero";
  }
  if (const auto& slab = clipping.slab) {
    if (!std::isfinite(slab->offsetMm) || !std::isfinite(slab->thicknessMm))
      return "the slab has a non-finite number";
    if (slab->thicknessMm <= 0) return "the slab's thickness is not above 0";
  }
  return "";
}

}  // namespace angio
