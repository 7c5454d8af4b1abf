#include "core/reference_raycaster.h"

#include <atomic>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/compositing.h"
#include "core/volume_sampling.h"

namespace angio {

namespace {

// The reference reads every voxel through the label mask (all labels shown: the plain density).
glm::vec4 compositeDvr(const Volume& volume, const ViewGeometry& view, const glm::dvec3& origin,
                       SampleRange samples, const FrameTables& tables, RegionCursor regions,
                       const MaskedDensity& read, const RenderParams& params) {
  const Filter filter = params.sampling.filter;
  const glm::vec3 viewDir(view.viewDir);
  const RaySamples positions(volume, view, origin);
  RayAccumulator ray;
  for (long k = samples.first; k <= samples.last; ++k) {
    const glm::dvec3 q = positions.at(k);
    const Region region = regions.at(double(k) * view.sampleMm);
    const SampleTable* table = tables.of(region, sampleLabel(volume, q, filter));
    if (!table) continue;  // a clipped region
    const glm::vec4 rgba = (*table)[tableIndex(sampleDensity(volume, q, filter, read))];
    if (rgba.a <= 0.f) continue;  // transparent: contributes nothing, shading not needed
    ray.add(rgba, shadingFactor(params.shading, sampleGradient(volume, q, filter, read), viewDir));
    if (ray.opacity >= params.sampling.ert) break;
  }
  return ray.pixel();
}

// MIP ignores the TFs but not the clipping: a clipped region contributes no maximum.
glm::vec4 compositeMip(const Volume& volume, const ViewGeometry& view, const glm::dvec3& origin,
                       SampleRange samples, const FrameTables& tables, RegionCursor regions,
                       const MaskedDensity& read, const RenderParams& params) {
  if (samples.empty()) return glm::vec4(0.f);
  const RaySamples positions(volume, view, origin);
  float maximum = 0.f;
  for (long k = samples.first; k <= samples.last; ++k)
    if (tables.of(regions.at(double(k) * view.sampleMm)))
      maximum = std::max(maximum, sampleDensity(volume, positions.at(k), params.sampling.filter, read));
  return mipPixel(maximum, params.mip);
}

}  // namespace

Image renderReference(const Volume& volume, const TfTable& table, const RenderParams& params,
                      const std::function<void(double)>& progress) {
  return renderReference(volume, singleTable(table), params, progress);
}

Image renderReference(const Volume& volume, const RegionTables& regionTables, const RenderParams& params,
                      const std::function<void(double)>& progress) {
  const ViewGeometry view = makeViewGeometry(volume, params);
  Image image = makeImage(view.width, view.height);
  const FrameTables tables = frameTables(regionTables, params.sampling.osd);
  const MaskedDensity read =
      regionTables.labels ? regionTables.labels->density() : LabelTables().density();
  std::atomic<int> rowsDone{0};
  tbb::parallel_for(tbb::blocked_range<int>(0, view.height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < view.width; ++x) {
        const glm::dvec3 origin = view.rayOrigin(x, y);
        const SampleRange samples = sampleRange(view, origin);
        const RegionCursor regions(regionTables.regions, x, y);
        image.at(x, y) =
            params.compositing == Compositing::mip
                ? compositeMip(volume, view, origin, samples, tables, regions, read, params)
                : compositeDvr(volume, view, origin, samples, tables, regions, read, params);
      }
    const int done = rowsDone += int(rows.size());
    if (progress) progress(double(done) / view.height);
  });
  return image;
}

}  // namespace angio
