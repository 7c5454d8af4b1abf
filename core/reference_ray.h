#pragma once
// One ray of the rendering model, sample by sample, nothing skipped (but what the view's clipping
// cuts away, core/clip_interval.h): the reference raycaster's
// pixel and the 3-D pick's walk (core/ray_pick.h), so a click finds its point by the same ray
// model the image was rendered with.
#include <algorithm>

#include "core/clip_interval.h"
#include "core/compositing.h"
#include "core/view_geometry.h"
#include "core/volume_sampling.h"

namespace angio {

// What a reference ray walks over.
struct RayScene {
  const Volume& volume;
  const ViewGeometry& view;
  const FrameTables& tables;
  const MaskedDensity& read;  // the labels' mask (all shown: the plain density)
  const RenderParams& params;
};

// DVR front to back. After each composited sample k, stop(ray, k) may end the ray (early ray
// termination, a pick's opacity threshold).
template <class Stop>
RayAccumulator compositeDvr(const RayScene& s, const glm::dvec3& origin, RegionCursor regions,
                            Stop&& stop) {
  const Filter filter = s.params.sampling.filter;
  const glm::vec3 viewDir(s.view.viewDir);
  const RaySamples positions(s.volume, s.view, origin);
  const SampleRange samples = clippedSampleRange(s.view, s.params.clipping, origin);
  RayAccumulator ray;
  for (long k = samples.first; k <= samples.last; ++k) {
    const glm::dvec3 q = positions.at(k);
    const Region region = regions.at(double(k) * s.view.sampleMm);
    const SampleTable* table = s.tables.of(region, sampleLabel(s.volume, q, filter));
    if (!table) continue;  // a clipped region
    const glm::vec4 rgba = (*table)[tableIndex(sampleDensity(s.volume, q, filter, s.read))];
    if (rgba.a <= 0.f) continue;  // transparent: contributes nothing, shading not needed
    ray.add(rgba, shadingFactor(s.params.shading, sampleGradient(s.volume, q, filter, s.read), viewDir));
    if (stop(ray, k)) break;
  }
  return ray;
}

// MIP: the largest density along the ray and the first sample that has it (sample indices are
// negative in front of P0). MIP ignores the TFs but not the clipping: a clipped region contributes
// no maximum.
struct RayMaximum {
  float density = 0.f;
  long sample = 0;
  bool found = false;  // some sample was not clipped
};

inline RayMaximum maximumAlongRay(const RayScene& s, const glm::dvec3& origin, RegionCursor regions) {
  const RaySamples positions(s.volume, s.view, origin);
  const SampleRange samples = clippedSampleRange(s.view, s.params.clipping, origin);
  RayMaximum maximum;
  for (long k = samples.first; k <= samples.last; ++k) {
    if (!s.tables.of(regions.at(double(k) * s.view.sampleMm))) continue;
    const float d = sampleDensity(s.volume, positions.at(k), s.params.sampling.filter, s.read);
    if (!maximum.found || d > maximum.density) maximum = {d, k, true};
  }
  return maximum;
}

}  // namespace angio
