#pragma once
// One ray of the rendering model, sample by sample, nothing skipped (but what the view's clipping
// cuts away, core/clip_interval.h): the reference raycaster's
// pixel and the 3-D pick's walk (core/ray_pick.h), so a click finds its point by the same ray
// model the image was rendered with.
#include <algorithm>

#include "core/clip_interval.h"
#include "core/compositing.h"
#include "core/preintegration.h"
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
  // Pre-integrated classification (params.sampling.preintegrated): the tables, slot for slot.
  const PreintegratedTables* segments = nullptr;
};

// Pre-integrated classification: the segment from sample k - 1 (whatever its region; outside the
// domain its clamped density) to k, classified with the TF of sample k's region and label.
inline glm::vec4 preintegratedSample(const RayScene& s, const RaySamples& positions, long k,
                                     Region region) {
  const Filter filter = s.params.sampling.filter;
  const glm::dvec3 q = positions.at(k);
  return s.segments->of(region, sampleLabel(s.volume, q, filter), s.tables)
      .segment(sampleDensity(s.volume, positions.at(k - 1), filter, s.read),
               sampleDensity(s.volume, q, filter, s.read));
}

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
    const glm::vec4 rgba = s.segments ? preintegratedSample(s, positions, k, region)
                                      : (*table)[tableIndex(sampleDensity(s.volume, q, filter, s.read))];
    if (rgba.a <= 0.f) continue;  // transparent: contributes nothing, shading not needed
    float shade = shadingFactor(s.params.shading, sampleGradient(s.volume, q, filter, s.read), viewDir);
    // Pre-integrated: the segment's emission shaded by the mean of its ends' shading factors.
    if (s.segments && s.params.shading.enabled)
      shade =
          0.5f * (shadingFactor(s.params.shading,
                                sampleGradient(s.volume, positions.at(k - 1), filter, s.read), viewDir) +
                  shade);
    ray.add(rgba, shade);
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
