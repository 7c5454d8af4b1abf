#include "core/slice_tiles.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

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

// What a volume without labels keeps of a window of voxels: the density range.
struct PlainSummary {
  Range densities;
  void add(Voxel v) { densities.add(std::uint16_t(densityOf(v))); }
  void add(const PlainSummary& s) { densities.add(s.densities); }
};

// With labels: the unlabelled and the labelled voxels' ranges apart, and the labels that occur.
struct LabelledSummary {
  Range densities;  // unlabelled
  Range labelled;
  std::uint16_t bits = 0;
  void add(Voxel v) {
    const int label = labelOf(v);
    (label == 0 ? densities : labelled).add(std::uint16_t(densityOf(v)));
    bits |= std::uint16_t(1u << label);
  }
  void add(const LabelledSummary& s) {
    densities.add(s.densities);
    labelled.add(s.labelled);
    bits |= s.bits;
  }
};

// Voxel window of tile t, clamped to [0, n - 1]: [t*T, t*T + T] for the cells of the tile
// (nearest, trilinear), one more voxel on each side for the mean filter.
std::pair<int, int> tileWindow(int tile, int n, int reach) {
  return {std::max(tile * kTileSize - reach, 0), std::min(tile * kTileSize + kTileSize + reach, n - 1)};
}

// Separable summary over one slice: first along b for every c line, then along c.
template <class Summary>
void summariseSlice(const Volume& volume, const SliceTiles& tiles, int slice, int reach,
                    std::vector<Summary>& lineSummaries, Summary* out) {
  const glm::ivec3 dims = volume.dims;
  const int nb = dims[tiles.axisB], nc = dims[tiles.axisC];
  glm::ivec3 stride(1, dims.x, dims.x * dims.y);
  const std::size_t sliceBase = std::size_t(slice) * stride[int(tiles.axis)];
  const int strideB = stride[tiles.axisB], strideC = stride[tiles.axisC];
  lineSummaries.assign(std::size_t(nc) * tiles.tilesB, Summary{});
  for (int c = 0; c < nc; ++c) {
    const Voxel* line = volume.voxels.data() + sliceBase + std::size_t(c) * strideC;
    for (int tb = 0; tb < tiles.tilesB; ++tb) {
      const auto [lo, hi] = tileWindow(tb, nb, reach);
      Summary r;
      for (int b = lo; b <= hi; ++b) r.add(line[std::size_t(b) * strideB]);
      lineSummaries[std::size_t(c) * tiles.tilesB + tb] = r;
    }
  }
  for (int tc = 0; tc < tiles.tilesC; ++tc) {
    const auto [lo, hi] = tileWindow(tc, nc, reach);
    for (int tb = 0; tb < tiles.tilesB; ++tb) {
      Summary r;
      for (int c = lo; c <= hi; ++c) r.add(lineSummaries[std::size_t(c) * tiles.tilesB + tb]);
      out[std::size_t(tc) * tiles.tilesB + tb] = r;
    }
  }
}

void store(const std::vector<PlainSummary>& summaries, TileRanges& ranges) {
  ranges.minDensity.resize(summaries.size());
  ranges.maxDensity.resize(summaries.size());
  for (std::size_t n = 0; n < summaries.size(); ++n) {
    ranges.minDensity[n] = summaries[n].densities.lo;
    ranges.maxDensity[n] = summaries[n].densities.hi;
  }
}

void store(const std::vector<LabelledSummary>& summaries, TileRanges& ranges) {
  const std::size_t count = summaries.size();
  for (auto* v : {&ranges.minDensity, &ranges.maxDensity, &ranges.labelledMin, &ranges.labelledMax,
                  &ranges.labelBits})
    v->resize(count);
  for (std::size_t n = 0; n < count; ++n) {
    const LabelledSummary& s = summaries[n];
    ranges.minDensity[n] = s.densities.lo, ranges.maxDensity[n] = s.densities.hi;
    ranges.labelledMin[n] = s.labelled.lo, ranges.labelledMax[n] = s.labelled.hi;
    ranges.labelBits[n] = s.bits;
  }
}

template <class Summary>
void summariseTiles(const Volume& volume, SliceTiles& tiles) {
  const std::size_t perSlice = tiles.tilesPerSlice();
  std::vector<Summary> cells(perSlice * tiles.slices), wide(perSlice * tiles.slices);
  tbb::parallel_for(0, tiles.slices, [&](int slice) {
    std::vector<Summary> lineSummaries;
    summariseSlice(volume, tiles, slice, 0, lineSummaries, cells.data() + perSlice * slice);
    summariseSlice(volume, tiles, slice, 1, lineSummaries, wide.data() + perSlice * slice);
  });
  store(cells, tiles.cells);
  store(wide, tiles.wide);
}

bool anyLabel(const Volume& volume) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, volume.voxels.size()), false,
      [&](const tbb::blocked_range<std::size_t>& range, bool found) {
        Voxel bits = 0;
        for (std::size_t n = range.begin(); n != range.end(); ++n) bits |= volume.voxels[n];
        return found || labelOf(bits) != 0;
      },
      [](bool a, bool b) { return a || b; });
}

std::size_t bytesOf(const TileRanges& r) {
  std::size_t bytes = 0;
  for (const auto* v : {&r.minDensity, &r.maxDensity, &r.labelledMin, &r.labelledMax, &r.labelBits})
    bytes += v->size() * sizeof(std::uint16_t);
  return bytes;
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
  tiles.labelled = anyLabel(volume);
  if (tiles.labelled) summariseTiles<LabelledSummary>(volume, tiles);
  else summariseTiles<PlainSummary>(volume, tiles);
  return tiles;
}

std::size_t SliceTiles::memoryBytes() const { return bytesOf(cells) + bytesOf(wide); }

int cellBase(double q, int n) {
  return std::min(int(std::floor(std::clamp(q, 0.0, double(n - 1)))), std::max(n - 2, 0));
}

SliceSpan slicesReadAt(const SliceTiles& tiles, double qa, Filter filter) {
  const int base = cellBase(qa, tiles.slices);
  const int reach = filter == Filter::mean ? 1 : 0;
  return {std::max(base - reach, 0), std::min(base + 1 + reach, tiles.slices - 1)};
}

}  // namespace angio
