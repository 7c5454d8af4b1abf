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

// Voxel window [t*T - 1, t*T + T + 1] of tile t, clamped to [0, n - 1].
std::pair<int, int> tileWindow(int tile, int n) {
  return {std::max(tile * kTileSize - 1, 0), std::min(tile * kTileSize + kTileSize + 1, n - 1)};
}

// Separable min/max over one slice: first along b for every c line, then along c.
void rangesOfSlice(const Volume& volume, const SliceTiles& tiles, int slice, std::vector<Range>& lineRanges,
                   Range* out) {
  const glm::ivec3 dims = volume.dims;
  const int nb = dims[tiles.axisB], nc = dims[tiles.axisC];
  glm::ivec3 stride(1, dims.x, dims.x * dims.y);
  const std::size_t sliceBase = std::size_t(slice) * stride[int(tiles.axis)];
  const int strideB = stride[tiles.axisB], strideC = stride[tiles.axisC];
  lineRanges.assign(std::size_t(nc) * tiles.tilesB, Range{});
  for (int c = 0; c < nc; ++c) {
    const Voxel* line = volume.voxels.data() + sliceBase + std::size_t(c) * strideC;
    for (int tb = 0; tb < tiles.tilesB; ++tb) {
      const auto [lo, hi] = tileWindow(tb, nb);
      Range r;
      for (int b = lo; b <= hi; ++b) r.add(std::uint16_t(densityOf(line[std::size_t(b) * strideB])));
      lineRanges[std::size_t(c) * tiles.tilesB + tb] = r;
    }
  }
  for (int tc = 0; tc < tiles.tilesC; ++tc) {
    const auto [lo, hi] = tileWindow(tc, nc);
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
  std::vector<Range> ranges(perSlice * tiles.slices);
  tbb::parallel_for(0, tiles.slices, [&](int slice) {
    thread_local std::vector<Range> lineRanges;
    rangesOfSlice(volume, tiles, slice, lineRanges, ranges.data() + perSlice * slice);
  });
  tiles.minDensity.resize(ranges.size());
  tiles.maxDensity.resize(ranges.size());
  for (std::size_t n = 0; n < ranges.size(); ++n) {
    tiles.minDensity[n] = ranges[n].lo;
    tiles.maxDensity[n] = ranges[n].hi;
  }
  return tiles;
}

SliceSpan slicesReadAt(const SliceTiles& tiles, double qa) {
  const int base = int(std::floor(std::clamp(qa, 0.0, double(tiles.slices - 1))));
  return {std::max(base - 1, 0), std::min(base + 2, tiles.slices - 1)};
}

std::vector<std::uint8_t> classifyTiles(const SliceTiles& tiles, const TfTable& table) {
  std::vector<std::uint8_t> visible(tiles.minDensity.size());
  tbb::parallel_for(std::size_t(0), visible.size(), [&](std::size_t n) {
    visible[n] = table.anyVisible(tiles.minDensity[n], tiles.maxDensity[n]);
  });
  return visible;
}

}  // namespace angio
