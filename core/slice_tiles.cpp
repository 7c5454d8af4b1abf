#include "core/slice_tiles.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

namespace angio {

namespace {

struct Range {
  std::uint16_t lo = 0xFFFF;
  std::uint16_t hi = 0;
  void add(std::uint16_t d) {
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  void add(const Range& r) {
    lo = std::min(lo, r.lo);
    hi = std::max(hi, r.hi);
  }
};

// Voxel window of tile t, clamped to [0, n - 1]: [t*T, t*T + T] for the cells of the tile
// (nearest, trilinear), one more voxel on each side for the mean filter.
std::pair<int, int> tileWindow(int tile, int n, int reach) {
  return {std::max(tile * kTileSize - reach, 0), std::min(tile * kTileSize + kTileSize + reach, n - 1)};
}

// Separable min/max over one slice: first along b for every c line, then along c.
void rangesOfSlice(const Volume& volume, const SliceTiles& tiles, int slice, int reach,
                   std::vector<Range>& lineRanges, Range* out) {
  const glm::ivec3 dims = volume.dims;
  const int nb = dims[tiles.axisB], nc = dims[tiles.axisC];
  glm::ivec3 stride(1, dims.x, dims.x * dims.y);
  const std::size_t sliceBase = std::size_t(slice) * stride[int(tiles.axis)];
  const int strideB = stride[tiles.axisB], strideC = stride[tiles.axisC];
  lineRanges.assign(std::size_t(nc) * tiles.tilesB, Range{});
  for (int c = 0; c < nc; ++c) {
    const Voxel* line = volume.voxels.data() + sliceBase + std::size_t(c) * strideC;
    for (int tb = 0; tb < tiles.tilesB; ++tb) {
      const auto [lo, hi] = tileWindow(tb, nb, reach);
      Range r;
      for (int b = lo; b <= hi; ++b) r.add(std::uint16_t(densityOf(line[std::size_t(b) * strideB])));
      lineRanges[std::size_t(c) * tiles.tilesB + tb] = r;
    }
  }
  for (int tc = 0; tc < tiles.tilesC; ++tc) {
    const auto [lo, hi] = tileWindow(tc, nc, reach);
    for (int tb = 0; tb < tiles.tilesB; ++tb) {
      Range r;
      for (int c = lo; c <= hi; ++c) r.add(lineRanges[std::size_t(c) * tiles.tilesB + tb]);
      out[std::size_t(tc) * tiles.tilesB + tb] = r;
    }
  }
}

}  // namespace

SliceTiles buildSliceTiles(const Volume& volume, Axis axis) {
  SliceTiles tiles;
  tiles.axis = axis;
  tiles.axisB = (int(axis) + 1) % 3;
  tiles.axisC = (int(axis) + 2) % 3;
  tiles.slices = volume.dims[int(axis)];
  tiles.tilesB = (volume.dims[tiles.axisB] + kTileSize - 1) / kTileSize;
  tiles.tilesC = (volume.dims[tiles.axisC] + kTileSize - 1) / kTileSize;
  const std::size_t perSlice = tiles.tilesPerSlice();
  std::vector<Range> cells(perSlice * tiles.slices), wide(perSlice * tiles.slices);
  tbb::parallel_for(0, tiles.slices, [&](int slice) {
    thread_local std::vector<Range> lineRanges;
    rangesOfSlice(volume, tiles, slice, 0, lineRanges, cells.data() + perSlice * slice);
    rangesOfSlice(volume, tiles, slice, 1, lineRanges, wide.data() + perSlice * slice);
  });
  auto store = [](const std::vector<Range>& ranges, std::vector<std::uint16_t>& lo,
                  std::vector<std::uint16_t>& hi) {
    lo.resize(ranges.size());
    hi.resize(ranges.size());
    for (std::size_t n = 0; n < ranges.size(); ++n) lo[n] = ranges[n].lo, hi[n] = ranges[n].hi;
  };
  store(cells, tiles.minDensity, tiles.maxDensity);
  store(wide, tiles.wideMinDensity, tiles.wideMaxDensity);
  return tiles;
}

int cellBase(double q, int n) {
  return std::min(int(std::floor(std::clamp(q, 0.0, double(n - 1)))), std::max(n - 2, 0));
}

SliceSpan slicesReadAt(const SliceTiles& tiles, double qa, Filter filter) {
  const int base = cellBase(qa, tiles.slices);
  const int reach = filter == Filter::mean ? 1 : 0;
  return {std::max(base - reach, 0), std::min(base + 1 + reach, tiles.slices - 1)};
}

std::vector<std::uint8_t> classifyTiles(const SliceTiles& tiles, const TfTable& table) {
  std::vector<std::uint8_t> visible(tiles.minDensity.size());
  tbb::parallel_for(std::size_t(0), visible.size(), [&](std::size_t n) {
    visible[n] = std::uint8_t(
        (table.anyVisible(tiles.minDensity[n], tiles.maxDensity[n]) ? kCellsVisible : 0) |
        (table.anyVisible(tiles.wideMinDensity[n], tiles.wideMaxDensity[n]) ? kWideVisible : 0));
  });
  return visible;
}

}  // namespace angio
