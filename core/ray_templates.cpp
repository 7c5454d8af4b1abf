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
  // Any row inside the axis extent has the same in-plane samples; use the domain's middle (not
  // the image's, which an image window may move above or below the domain).
  glm::dvec3 origin = view.rayOrigin(x, 0);
  origin[view.axis] = view.extent[view.axis] * 0.5;
  const SampleRange range = sampleRange(view, origin);
  const int nb = volume.dims[tiles.axisB], nc = volume.dims[tiles.axisC];
  const RaySamples positions(volume, view, origin);
  std::vector<TileRun> runs;
  for (long k = range.first; k <= range.last; ++k) {
    const glm::dvec3 q = positions.at(k);
    const int tile = tileOf(q[tiles.axisC], nc) * tiles.tilesB + tileOf(q[tiles.axisB], nb);
    if (!runs.empty() && runs.back().tile == tile) ++runs.back().count;
    else runs.push_back({tile, 1, k});
  }
  return runs;
}

// Appends a column's runs, opening a new group whenever the ray enters another tile group (a
// straight ray never comes back to a group it left).
void appendColumn(const SliceTiles& tiles, const std::vector<TileRun>& runs, RayTemplates& templates) {
  templates.columnBegin.push_back(std::uint32_t(templates.groups.size()));
  for (TileRun run : runs) {
    const int group = tiles.groupOf(run.tile);
    run.bit = std::uint8_t(tiles.groupBit(run.tile));
    const auto index = std::uint32_t(templates.runs.size());
    if (templates.groups.size() == templates.columnBegin.back() ||
        templates.groups.back().group != group)
      templates.groups.push_back({group, index, index});
    templates.runs.push_back(run);
    templates.groups.back().endRun = index + 1;
    templates.groups.back().crossed |= std::uint64_t{1} << run.bit;
  }
}

// The position of a group in front-to-back order for rays with this in-plane direction.
std::vector<std::uint32_t> groupRanks(const SliceTiles& tiles, const ViewGeometry& view) {
  const bool backwardB = view.viewDir[tiles.axisB] < 0, backwardC = view.viewDir[tiles.axisC] < 0;
  const int nb = tiles.groupsB(), nc = tiles.groupsC();
  std::vector<std::uint32_t> rank(std::size_t(nb) * nc);
  for (int gc = 0; gc < nc; ++gc)
    for (int gb = 0; gb < nb; ++gb)
      rank[std::size_t(gc) * nb + gb] =
          std::uint32_t((backwardC ? nc - 1 - gc : gc) * nb + (backwardB ? nb - 1 - gb : gb));
  return rank;
}

// Counting sort of every column's group runs by group rank, columns ascending within a rank.
void sortVisitsFrontToBack(const SliceTiles& tiles, const ViewGeometry& view, RayTemplates& templates) {
  const std::vector<std::uint32_t> rank = groupRanks(tiles, view);
  templates.rankGroup.assign(rank.size(), 0);
  for (std::size_t g = 0; g < rank.size(); ++g) templates.rankGroup[rank[g]] = std::int32_t(g);
  std::vector<std::uint32_t>& begin = templates.rankBegin;
  begin.assign(rank.size() + 1, 0);
  for (const GroupRun& group : templates.groups) ++begin[rank[group.group] + 1];
  for (std::size_t r = 1; r < begin.size(); ++r) begin[r] += begin[r - 1];
  std::vector<std::uint32_t> next(begin.begin(), begin.end() - 1);
  templates.visits.resize(templates.groups.size());
  for (std::uint32_t x = 0; x + 1 < templates.columnBegin.size(); ++x)
    for (std::uint32_t g = templates.columnBegin[x]; g < templates.columnBegin[x + 1]; ++g)
      templates.visits[next[rank[templates.groups[g].group]]++] = {x, g};
}

}  // namespace

RayTemplates buildRayTemplates(const Volume& volume, const ViewGeometry& view, const SliceTiles& tiles,
                               const std::atomic<bool>* cancel) {
  std::vector<std::vector<TileRun>> perColumn(view.width);
  const auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
  tbb::parallel_for(0, view.width, [&](int x) {
    if (!cancelled()) perColumn[x] = columnRuns(volume, view, tiles, x);
  });
  RayTemplates templates;
  // Gathering and ordering the runs is serial (templates took up to 150 ms per frame for a zoomed
  // view of a 1024^2 volume): a cancelled frame must not wait for it.
  if (cancelled()) return templates;
  templates.columnBegin.reserve(view.width + 1);
  for (const auto& runs : perColumn) appendColumn(tiles, runs, templates);
  templates.columnBegin.push_back(std::uint32_t(templates.groups.size()));
  sortVisitsFrontToBack(tiles, view, templates);
  return templates;
}

}  // namespace angio
