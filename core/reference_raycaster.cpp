#include "core/reference_raycaster.h"

#include <atomic>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/reference_ray.h"

namespace angio {

namespace {

glm::vec4 dvrPixel(const RayScene& scene, const glm::dvec3& origin, RegionCursor regions) {
  const double ert = scene.params.sampling.ert;
  return compositeDvr(scene, origin, regions,
                      [ert](const RayAccumulator& ray, long) { return ray.opacity >= ert; })
      .pixel();
}

// A ray that misses the volume, or whose samples the clipping all cuts away, is black; one through
// it shows its maximum through the window.
glm::vec4 mipRayPixel(const RayScene& scene, const glm::dvec3& origin, RegionCursor regions) {
  if (clippedSampleRange(scene.view, scene.params.clipping, origin).empty()) return glm::vec4(0.f);
  return mipPixel(maximumAlongRay(scene, origin, regions).density, scene.params.mip);
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
  const MaskedDensity read = regionTables.density();
  std::optional<PreintegratedTables> segments;
  if (params.sampling.preintegrated) segments = preintegratedTables(regionTables, params.sampling.osd);
  const RayScene scene{volume, view, tables, read, params, segments ? &*segments : nullptr};
  std::atomic<int> rowsDone{0};
  tbb::parallel_for(tbb::blocked_range<int>(0, view.height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < view.width; ++x) {
        const glm::dvec3 origin = view.rayOrigin(x, y);
        const RegionCursor regions(regionTables.regions, x, y);
        image.at(x, y) = params.compositing == Compositing::mip ? mipRayPixel(scene, origin, regions)
                                                                : dvrPixel(scene, origin, regions);
      }
    const int done = rowsDone += int(rows.size());
    if (progress) progress(double(done) / view.height);
  });
  return image;
}

}  // namespace angio
