#include "core/ray_pick.h"

#include "core/reference_ray.h"

namespace angio {

namespace {

// The ray origin (t = 0) through a continuous image point (ViewGeometry::rayOrigin at x + 0.5).
glm::dvec3 originAt(const ViewGeometry& view, glm::dvec2 imagePoint) {
  const double h = (imagePoint.x - view.width * 0.5) * view.pixelMm;
  const double v = (view.height * 0.5 - imagePoint.y) * view.pixelMm;
  return view.centre + h * view.right + v * view.up;
}

PickedPoint pointAt(const RayScene& s, const glm::dvec3& origin, long k) {
  const glm::dvec3 q = RaySamples(s.volume, s.view, origin).at(k);
  return {q * s.volume.spacing, sampleDensity(s.volume, q, s.params.sampling.filter, s.read)};
}

}  // namespace

std::optional<PickedPoint> pickPoint(const Volume& volume, const RegionTables& tables,
                                     const RenderParams& params, glm::dvec2 imagePoint, double opacity) {
  const ViewGeometry view = makeViewGeometry(volume, params);
  const RegionTables outsideOnly{nullptr, nullptr, nullptr, tables.outside, tables.labels};
  const FrameTables frame = frameTables(outsideOnly, params.sampling.osd);
  const MaskedDensity read = tables.density();
  const RayScene scene{volume, view, frame, read, params};
  const glm::dvec3 origin = originAt(view, imagePoint);
  if (params.compositing == Compositing::mip) {
    const RayMaximum maximum = maximumAlongRay(scene, origin, {});
    if (!maximum.found) return std::nullopt;
    return pointAt(scene, origin, maximum.sample);
  }
  std::optional<long> reached;
  compositeDvr(scene, origin, {}, [&](const RayAccumulator& ray, long k) {
    if (ray.opacity < opacity) return false;
    reached = k;
    return true;
  });
  if (!reached) return std::nullopt;
  return pointAt(scene, origin, *reached);
}

std::optional<PickedPoint> pickLabelled(const Volume& volume, const RenderParams& params,
                                        glm::dvec2 imagePoint) {
  const ViewGeometry view = makeViewGeometry(volume, params);
  const glm::dvec3 origin = originAt(view, imagePoint);
  const RaySamples positions(volume, view, origin);
  const SampleRange samples = clippedSampleRange(view, params.clipping, origin);
  for (long k = samples.first; k <= samples.last; ++k) {
    const glm::dvec3 q = positions.at(k);
    if (sampleLabel(volume, q, params.sampling.filter) == 0) continue;
    return PickedPoint{q * volume.spacing, sampleDensity(volume, q, params.sampling.filter)};
  }
  return std::nullopt;
}

}  // namespace angio
