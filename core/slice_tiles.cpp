#include "core/slice_tiles.h"

#include <algorithm>
#include <cmath>
#include <mutex>

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

// The scale of a group whose tiles span [lo, hi]: the least shift that puts hi - lo in a byte.
PackedRanges::Scale scaleFor(const Range& span) {
  if (span.lo > span.hi) return {};
  std::uint8_t shift = 0;
  while (((span.hi - span.lo) >> shift) > 255) ++shift;
  return {span.lo, shift};
}

void allocate(PackedRanges& ranges, std::size_t tiles, std::size_t groups) {
  ranges.minOffset.resize(tiles);
  ranges.maxOffset.resize(tiles);
  ranges.scale.resize(groups);
}

void allocate(const SliceTiles& tiles, TileRanges& ranges) {
  const std::size_t count = std::size_t(tiles.tilesPerSlice()) * tiles.slices;
  const std::size_t groups = std::size_t(tiles.groupsPerSlice()) * tiles.slices;
  allocate(ranges.unlabelled, count, groups);
  if (!tiles.labelled) return;
  allocate(ranges.labelled, count, groups);
  ranges.labelBits.resize(count);
}

// Packs one slice's exact tile ranges (rangeOf(exact[tileC * tilesB + tileB])) group by group.
template <class Summary, class RangeOf>
void packSlice(const SliceTiles& tiles, int slice, const std::vector<Summary>& exact, RangeOf&& rangeOf,
               PackedRanges& out) {
  for (int gc = 0; gc < tiles.groupsC(); ++gc)
    for (int gb = 0; gb < tiles.groupsB(); ++gb) {
      const int tcEnd = std::min((gc + 1) * kGroupTiles, tiles.tilesC);
      const int tbEnd = std::min((gb + 1) * kGroupTiles, tiles.tilesB);
      Range span;
      for (int tc = gc * kGroupTiles; tc < tcEnd; ++tc)
        for (int tb = gb * kGroupTiles; tb < tbEnd; ++tb)
          span.add(rangeOf(exact[tc * tiles.tilesB + tb]));
      PackedRanges::Scale scale = scaleFor(span);
      if (span.lo <= span.hi) scale.top = std::uint8_t((span.hi - scale.base) >> scale.shift);
      out.scale[tiles.ref(slice, gc * kGroupTiles, gb * kGroupTiles).group] = scale;
      for (int tc = gc * kGroupTiles; tc < tcEnd; ++tc)
        for (int tb = gb * kGroupTiles; tb < tbEnd; ++tb) {
          const Range r = rangeOf(exact[tc * tiles.tilesB + tb]);
          const std::size_t n = tiles.ref(slice, tc, tb).tile;
          const bool empty = r.lo > r.hi;
          out.minOffset[n] =
              empty ? PackedRanges::kEmptyMin : std::uint8_t((r.lo - scale.base) >> scale.shift);
          out.maxOffset[n] =
              empty ? PackedRanges::kEmptyMax : std::uint8_t((r.hi - scale.base) >> scale.shift);
        }
    }
}

void pack(const SliceTiles& tiles, int slice, const std::vector<PlainSummary>& exact, TileRanges& out) {
  packSlice(
      tiles, slice, exact, [](const PlainSummary& s) { return s.densities; }, out.unlabelled);
}

void pack(const SliceTiles& tiles, int slice, const std::vector<LabelledSummary>& exact,
          TileRanges& out) {
  packSlice(
      tiles, slice, exact, [](const LabelledSummary& s) { return s.densities; }, out.unlabelled);
  packSlice(
      tiles, slice, exact, [](const LabelledSummary& s) { return s.labelled; }, out.labelled);
  const std::size_t first = std::size_t(slice) * tiles.tilesPerSlice();
  for (std::size_t n = 0; n < exact.size(); ++n) out.labelBits[first + n] = exact[n].bits;
}

template <class Summary>
Summary summaryOver(const std::vector<Summary>& columns, std::pair<int, int> window) {
  Summary summary;
  for (int b = window.first; b <= window.second; ++b) summary.add(columns[b]);
  return summary;
}

// Where one slice's voxels are: line c along b is voxels[first + c strideC + b strideB].
struct SliceLayout {
  const Voxel* first = nullptr;
  std::size_t strideB = 0, strideC = 0;
  int nb = 0, nc = 0;
};

SliceLayout sliceLayout(const Volume& volume, const SliceTiles& tiles, int slice) {
  const glm::ivec3 dims = volume.dims;
  const std::size_t stride[3] = {1, std::size_t(dims.x), std::size_t(dims.x) * dims.y};
  return {volume.voxels.data() + slice * stride[int(tiles.axis)], stride[tiles.axisB],
          stride[tiles.axisC], dims[tiles.axisB], dims[tiles.axisC]};
}

// Adds line c's voxels to the column summaries (contiguous when rotating about k: vectorised).
template <class Summary>
void addLine(const SliceLayout& slice, int c, std::vector<Summary>& columns) {
  const Voxel* line = slice.first + c * slice.strideC;
  for (int b = 0; b < slice.nb; ++b) columns[b].add(line[b * slice.strideB]);
}

// Scratch of one worker: per b column (for one tile row), per tile (for one slice).
template <class Summary>
struct SliceScratch {
  std::vector<Summary> cellColumns, wideColumns;
  std::vector<Summary> cellTiles, wideTiles;
};

// One slice's tiles, separably: per tile row, every b column over the row's c window, then each
// tile over its b window; the mean filter's window adds one line before and after. Then packed.
template <class Summary>
void summariseSlice(const Volume& volume, SliceTiles& tiles, int slice, SliceScratch<Summary>& scratch) {
  const SliceLayout layout = sliceLayout(volume, tiles, slice);
  auto &cells = scratch.cellColumns, &wide = scratch.wideColumns;
  scratch.cellTiles.resize(tiles.tilesPerSlice());
  scratch.wideTiles.resize(tiles.tilesPerSlice());
  for (int tc = 0; tc < tiles.tilesC; ++tc) {
    const auto [lo, hi] = tileWindow(tc, layout.nc, 0);
    cells.assign(layout.nb, Summary{});
    for (int c = lo; c <= hi; ++c) addLine(layout, c, cells);
    wide = cells;
    if (lo > 0) addLine(layout, lo - 1, wide);
    if (hi < layout.nc - 1) addLine(layout, hi + 1, wide);
    for (int tb = 0; tb < tiles.tilesB; ++tb) {
      const std::size_t n = std::size_t(tc) * tiles.tilesB + tb;
      scratch.cellTiles[n] = summaryOver(cells, tileWindow(tb, layout.nb, 0));
      scratch.wideTiles[n] = summaryOver(wide, tileWindow(tb, layout.nb, 1));
    }
  }
  pack(tiles, slice, scratch.cellTiles, tiles.cells);
  pack(tiles, slice, scratch.wideTiles, tiles.wide);
}

template <class Summary>
void summariseTiles(const Volume& volume, SliceTiles& tiles,
                    const std::function<void(double)>& progress) {
  allocate(tiles, tiles.cells);
  allocate(tiles, tiles.wide);
  std::mutex reporting;  // progress is called one at a time, with growing fractions
  int slicesDone = 0;
  tbb::parallel_for(tbb::blocked_range<int>(0, tiles.slices), [&](const tbb::blocked_range<int>& range) {
    SliceScratch<Summary> scratch;
    for (int slice = range.begin(); slice != range.end(); ++slice)
      summariseSlice(volume, tiles, slice, scratch);
    if (!progress) return;
    const std::lock_guard<std::mutex> lock(reporting);
    slicesDone += int(range.size());
    progress(double(slicesDone) / tiles.slices);
  });
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
  return r.unlabelled.memoryBytes() + r.labelled.memoryBytes() +
         r.labelBits.size() * sizeof(std::uint16_t);
}

}  // namespace

SliceTiles buildSliceTiles(const Volume& volume, Axis axis,
                           const std::function<void(double)>& progress) {
  SliceTiles tiles;
  tiles.axis = axis;
  tiles.axisB = (int(axis) + 1) % 3;
  tiles.axisC = (int(axis) + 2) % 3;
  tiles.slices = volume.dims[int(axis)];
  tiles.tilesB = (volume.dims[tiles.axisB] + kTileSize - 1) / kTileSize;
  tiles.tilesC = (volume.dims[tiles.axisC] + kTileSize - 1) / kTileSize;
  tiles.labelled = anyLabel(volume);
  if (tiles.labelled) summariseTiles<LabelledSummary>(volume, tiles, progress);
  else summariseTiles<PlainSummary>(volume, tiles, progress);
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
