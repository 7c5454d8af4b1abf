#pragma once
// VesselGlyph ray regions for raycaster tests: per pixel, focus around depth 0 with a half-width
// that varies across the image (`minHalf` + (x * 7 + y * 3) mod `spread`), a gap of `gap`, then
// context up to `contextEnd` beyond the focus, so every ray's regions start and end elsewhere.
#include <cstddef>
#include <cstdint>

#include "core/region_intervals.h"
#include "core/transfer_function.h"
#include "core/view_geometry.h"

namespace angio::test_support {

inline RayRegions varyingRegions(const ViewGeometry& view, float minHalf, int spread, float gap,
                                 float contextEnd) {
  RayRegions regions;
  regions.width = view.width;
  regions.height = view.height;
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x) {
      regions.rayBegin.push_back(std::uint32_t(regions.intervals.size()));
      const float half = minHalf + float((x * 7 + y * 3) % spread);
      regions.intervals.push_back({-half, half, Region::focus});
      regions.intervals.push_back({half + gap, half + contextEnd, Region::context});
    }
  regions.rayBegin.push_back(std::uint32_t(regions.intervals.size()));
  return regions;
}

// The regions of the rays of `window` (a window of the image `wholeWidth` pixels wide whose regions
// are `whole`): the whole image's, pixel for pixel.
inline RayRegions cropRegions(const RayRegions& whole, int wholeWidth, const ViewGeometry& window) {
  RayRegions regions;
  regions.width = window.width;
  regions.height = window.height;
  for (int y = 0; y < window.height; ++y)
    for (int x = 0; x < window.width; ++x) {
      regions.rayBegin.push_back(std::uint32_t(regions.intervals.size()));
      const std::size_t n = std::size_t(window.windowY + y) * wholeWidth + window.windowX + x;
      regions.intervals.insert(regions.intervals.end(), whole.intervals.begin() + whole.rayBegin[n],
                               whole.intervals.begin() + whole.rayBegin[n + 1]);
    }
  regions.rayBegin.push_back(std::uint32_t(regions.intervals.size()));
  return regions;
}

// TFs for those regions on the phantom: the focus shows vessels and bone, the context the same
// densities faintly.
struct RegionTfTables {
  TfTable focus, context;
};
inline RegionTfTables vesselRegionTables() {
  TransferFunction vessels;
  vessels.points = {{-1024, {0, 0, 0}, 0},
                    {150, {1, 0.2f, 0.1f}, 0},
                    {300, {1, 0.4f, 0.3f}, 0.6},
                    {3071, {1, 1, 1}, 0.8}};
  TransferFunction context = vessels;
  context.points[2].opacity = 0.05;
  context.points[3].opacity = 0.1;
  return {buildTable(vessels), buildTable(context)};
}

}  // namespace angio::test_support
