#pragma once
// Ray traversal templates (thesis sec. 4.3.2): with parallel projection and rotation about one
// axis every image row has the same in-plane ray pattern, so the walk of each image column
// through the slice tiles is computed once per view and reused by every row. A column's template
// is a list of runs: consecutive samples k whose floor(q) lies in the same tile, grouped by the
// tile group (kGroupTiles^2 tiles) they lie in, so a ray leaps over an empty group in one step,
// and over a group where none of the tiles it crosses is visible with one test of a 64-bit mask.
#include <atomic>
#include <cstdint>
#include <vector>

#include "core/slice_tiles.h"
#include "core/view_geometry.h"

namespace angio {

struct TileRun {
  std::int32_t tile = 0;  // tileC * tilesB + tileB
  std::int32_t count = 0;
  long firstSample = 0;  // k of the first sample of the run
  std::uint8_t bit = 0;  // the tile's bit in its group's masks (SliceTiles::groupBit)
};

struct GroupRun {
  std::int32_t group = 0;      // groupC * groupsB + groupB
  std::uint32_t firstRun = 0;  // its tile runs: [firstRun, endRun)
  std::uint32_t endRun = 0;
  std::uint64_t crossed = 0;  // the bits of the tiles its runs cross
};

// One column's passage through one tile group: templates.groups[groupRun] of column `column`.
struct GroupVisit {
  std::uint32_t column = 0;
  std::uint32_t groupRun = 0;
};

struct RayTemplates {
  std::vector<std::uint32_t> columnBegin;  // groups of column x: [columnBegin[x], columnBegin[x + 1])
  std::vector<GroupRun> groups;
  std::vector<TileRun> runs;
  // Every column's group runs in one front-to-back order for all rays (thesis sec. 4.3.1, fig.
  // 4.4: the view's quadrant decides the order). A ray's group indices along b and along c each
  // change monotonically, so ordering groups by (c, b), each reversed where the ray direction's
  // component is negative, lists every ray's groups in its own order; columns follow by x within
  // a group. A row rendered in this order reads each group's voxels (32^2 of each slice it reads)
  // once for all rays through it, from the L1 cache, instead of once per ray.
  std::vector<GroupVisit> visits;
  // The visits through the group of rank r: [rankBegin[r], rankBegin[r + 1]), that group is
  // rankGroup[r]; so a row skips a group no ray can see there in one step.
  std::vector<std::uint32_t> rankBegin;
  std::vector<std::int32_t> rankGroup;
};

// Sample positions are computed with the same arithmetic as the raycasters (RaySamples),
// so the tile a run names is the tile of every sample in it.
// `cancel` (optional) set: stops early with templates that must not be used.
RayTemplates buildRayTemplates(const Volume& volume, const ViewGeometry& view, const SliceTiles& tiles,
                               const std::atomic<bool>* cancel = nullptr);

}  // namespace angio
