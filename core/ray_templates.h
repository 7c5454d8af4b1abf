#pragma once
// Ray traversal templates (thesis sec. 4.3.2): with parallel projection and rotation about one
// axis every image row has the same in-plane ray pattern, so the walk of each image column
// through the slice tiles is computed once per view and reused by every row. A column's template
// is a list of runs: consecutive samples k whose floor(q) lies in the same tile.
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

struct RayTemplates {
  std::vector<std::uint32_t> columnBegin;  // runs of column x: [columnBegin[x], columnBegin[x + 1])
  std::vector<TileRun> runs;
};

// Sample positions are computed with the same arithmetic as the raycasters (sampleCoordinate),
// so the tile a run names is the tile of every sample in it.
RayTemplates buildRayTemplates(const Volume& volume, const ViewGeometry& view, const SliceTiles& tiles);

}  // namespace angio
