#pragma once
// Ray traversal templates (thesis sec. 4.3.2): with parallel projection and rotation about one
// axis every image row has the same in-plane ray pattern, so the walk of each image column
// through the slice tiles is computed once per view and reused by every row. A column's template
// is a list of runs: consecutive samples k whose floor(q) lies in the same tile, grouped by the
// tile group (kGroupTiles^2 tiles) they lie in, so a ray leaps over an empty group in one step
// and only looks at the tiles of groups that may be visible.
#include <cstdint>
#include <vector>

#include "core/slice_tiles.h"
#include "core/view_geometry.h"

namespace angio {

struct TileRun {
  std::int32_t tile = 0;  // tileC * tilesB + tileB
  std::int32_t count = 0;
  long firstSample = 0;   // k of the first sample of the run
};

struct GroupRun {
  std::int32_t group = 0;      // groupC * groupsB + groupB
  std::uint32_t firstRun = 0;  // its tile runs: [firstRun, endRun)
  std::uint32_t endRun = 0;
};

struct RayTemplates {
  std::vector<std::uint32_t> columnBegin;  // groups of column x: [columnBegin[x], columnBegin[x + 1])
  std::vector<GroupRun> groups;
  std::vector<TileRun> runs;
};

// Sample positions are computed with the same arithmetic as the raycasters (RaySamples),
// so the tile a run names is the tile of every sample in it.
RayTemplates buildRayTemplates(const Volume& volume, const ViewGeometry& view, const SliceTiles& tiles);

}  // namespace angio
