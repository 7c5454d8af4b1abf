#include "core/ray_templates.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "core/compositing.h"

namespace angio {

namespace {

int tileOf(double q, int n) { return cellBase(q, n) / kTileSize; }

std::vector<TileRun> columnRuns(const Volume& volume, const ViewGeometry& view, const SliceTiles& tiles,
                                int x) {
  // Any row inside the axis extent has the same in-plane samples; use the middle one.
  glm::dvec3 origin = view.rayOrigin(x, 0);
  origin[view.axis] = view.centre[view.axis];
  const SampleRange range = sampleRange(view, origin);
  const int nb = volume.dims[tiles.axisB], nc = volume.dims[tiles.axisC];
  const RaySamples positions(volume, view, origin);
  std::vector<TileRun> runs;
  for (long k = range.first; k <= range.last; ++k) {
    const glm::dvec3 q = positions.at(k);
    const int tile = tileOf(q[tiles.axisC], nc) * tiles.tilesB + tileOf(q[tiles.axisB], nb);
    if (!runs.empty() && runs.back().tile == tile)
      ++runs.back().count;
    else
      runs.push_back({tile, 1, k});
  }
  return runs;
}

// Appends a column's runs, opening a new group whenever the ray enters another tile group (a
// straight ray never comes back to a group it left).
void appendColumn(const SliceTiles& tiles, const std::vector<TileRun>& runs, RayTemplates& templates) {
  templates.columnBegin.push_back(std::uint32_t(templates.groups.size()));
  for (const TileRun& run : runs) {
    const int group = tiles.groupOf(run.tile);
    const auto index = std::uint32_t(templates.runs.size());
    if (templates.groups.size() == templates.columnBegin.back() || templates.groups.back().group != group)
      templates.groups.push_back({group, index, index});
    templates.runs.push_back(run);
    templates.groups.back().endRun = index + 1;
  }
}

}  // namespace

RayTemplates buildRayTemplates(const Volume& volume, const ViewGeometry& view, const SliceTiles& tiles) {
  std::vector<std::vector<TileRun>> perColumn(view.width);
  tbb::parallel_for(0, view.width, [&](int x) { perColumn[x] = columnRuns(volume, view, tiles, x); });
  RayTemplates templates;
  templates.columnBegin.reserve(view.width + 1);
  for (const auto& runs : perColumn) appendColumn(tiles, runs, templates);
  templates.columnBegin.push_back(std::uint32_t(templates.groups.size()));
  return templates;
}

}  // namespace angio
