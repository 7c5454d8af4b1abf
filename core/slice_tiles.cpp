#include "core/slice_tiles.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <type_traits>

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
};

// With labels: the unlabelled and the labelled voxels' ranges apart, and the labels that occur.
struct LabelledSummary {
  Range densities;  // unlabelled
  Range labelled;
  std::uint16_t bits = 0;
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

// Where one slice's voxels are: line c along b is voxels[first + c strideC + b strideB].
struct SliceLayout {
  const Voxel* first = nullptr;
  std::size_t strideB = 0, strideC = 0;
  int nb = 0, nc = 0;
};

// The step in Volume::voxels between neighbours along `axis` (0 = i, 1 = j, 2 = k).
std::size_t strideAlong(const Volume& volume, int axis) {
  return axis == 0   ? 1
         : axis == 1 ? std::size_t(volume.dims.x)
                     : std::size_t(volume.dims.x) * volume.dims.y;
}

SliceLayout sliceLayout(const Volume& volume, const SliceTiles& tiles, int slice) {
  return {volume.voxels.data() + slice * strideAlong(volume, int(tiles.axis)),
          strideAlong(volume, tiles.axisB), strideAlong(volume, tiles.axisC), volume.dims[tiles.axisB],
          volume.dims[tiles.axisC]};
}

// A slice about j or k is made of `count` runs of `length` voxels along i, run r starting at
// Volume::voxels[first + r * step] (the rows j of a k slice, the rows i of each k of a j slice).
struct SliceRuns {
  std::size_t first = 0, step = 0;
  int count = 0, length = 0;
};

SliceRuns sliceRuns(const Volume& volume, Axis axis, int slice) {
  const std::size_t row = std::size_t(volume.dims.x), plane = row * volume.dims.y;
  if (axis == Axis::k) return {slice * plane, row, volume.dims.y, volume.dims.x};
  return {slice * row, plane, volume.dims.z, volume.dims.x};
}

// One slice as the volume will hold it once `overlay` is written, copied run after run into
// `buffer`; the overlay's voxels of the slice are found by one search, then a walk.
SliceLayout overlaidSlice(const Volume& volume, const SliceTiles& tiles, const LabelOverlay& overlay,
                          int slice, std::vector<Voxel>& buffer) {
  const SliceRuns runs = sliceRuns(volume, tiles.axis, slice);
  const std::size_t length = std::size_t(runs.length);
  buffer.resize(length * runs.count);
  const std::vector<std::size_t>& changed = overlay.voxels;
  auto next = std::lower_bound(changed.begin(), changed.end(), runs.first);
  for (int r = 0; r < runs.count; ++r) {
    const std::size_t start = runs.first + r * runs.step;
    Voxel* run = buffer.data() + r * length;
    std::copy_n(volume.voxels.data() + start, length, run);
    if (next != changed.end() && *next < start) next = std::lower_bound(next, changed.end(), start);
    for (; next != changed.end() && *next < start + length; ++next)
      run[*next - start] = withLabel(run[*next - start], overlay.labels[next - changed.begin()]);
  }
  const auto stride = [&](int axis) { return axis == 0 ? std::size_t(1) : length; };
  return {buffer.data(), stride(tiles.axisB), stride(tiles.axisC), volume.dims[tiles.axisB],
          volume.dims[tiles.axisC]};
}

// The summaries of every b column of one tile row, one array per quantity, so that adding a line
// (contiguous when rotating about k) vectorises.
struct PlainColumns {
  std::vector<Range> densities;

  void reset(int nb) { densities.assign(nb, Range{}); }
  void addLine(const SliceLayout& slice, int c) {
    const Voxel* line = slice.first + c * slice.strideC;
    for (int b = 0; b < slice.nb; ++b)
      densities[b].add(std::uint16_t(densityOf(line[b * slice.strideB])));
  }
  PlainSummary over(std::pair<int, int> window) const {
    PlainSummary summary;
    for (int b = window.first; b <= window.second; ++b) summary.densities.add(densities[b]);
    return summary;
  }
};

struct LabelledColumns {
  std::vector<Range> densities, labelled;
  std::vector<std::uint16_t> bits;

  void reset(int nb) {
    densities.assign(nb, Range{});
    labelled.assign(nb, Range{});
    bits.assign(nb, 0);
  }
  // Most lines hold no labelled voxel (labels mark organs, bone, the table): those add their
  // densities as a volume without labels does, and only bit 0.
  void addLine(const SliceLayout& slice, int c) {
    const Voxel* line = slice.first + c * slice.strideC;
    Voxel any = 0;
    for (int b = 0; b < slice.nb; ++b) any |= line[b * slice.strideB];
    if (labelOf(any) == 0) {
      for (int b = 0; b < slice.nb; ++b) densities[b].add(line[b * slice.strideB]);  // density == voxel
      for (int b = 0; b < slice.nb; ++b) bits[b] |= 1;
      return;
    }
    // Branch-free, so that it vectorises too: a voxel adds its density to one range and the
    // neutral value (an empty range's bound) to the other.
    for (int b = 0; b < slice.nb; ++b) {
      const Voxel v = line[b * slice.strideB];
      const std::uint16_t density = std::uint16_t(densityOf(v));
      const bool unlabelled = labelOf(v) == 0;
      densities[b].add(Range{unlabelled ? density : Range{}.lo, unlabelled ? density : Range{}.hi});
      labelled[b].add(Range{unlabelled ? Range{}.lo : density, unlabelled ? Range{}.hi : density});
    }
    for (int b = 0; b < slice.nb; ++b) bits[b] |= std::uint16_t(1u << labelOf(line[b * slice.strideB]));
  }
  LabelledSummary over(std::pair<int, int> window) const {
    LabelledSummary summary;
    for (int b = window.first; b <= window.second; ++b) {
      summary.densities.add(densities[b]);
      summary.labelled.add(labelled[b]);
      summary.bits |= bits[b];
    }
    return summary;
  }
};

template <class Summary>
using ColumnsOf =
    std::conditional_t<std::is_same_v<Summary, PlainSummary>, PlainColumns, LabelledColumns>;

// Scratch of one worker: per b column (for one tile row), per tile (for one slice).
template <class Summary>
struct SliceScratch {
  ColumnsOf<Summary> cellColumns, wideColumns;
  std::vector<Summary> cellTiles, wideTiles;
};

// One slice's tiles, separably: per tile row, every b column over the row's c window, then each
// tile over its b window; the mean filter's window adds one line before and after. Then packed.
template <class Summary>
void summariseSlice(const SliceLayout& layout, SliceTiles& tiles, int slice,
                    SliceScratch<Summary>& scratch) {
  auto &cells = scratch.cellColumns, &wide = scratch.wideColumns;
  scratch.cellTiles.resize(tiles.tilesPerSlice());
  scratch.wideTiles.resize(tiles.tilesPerSlice());
  for (int tc = 0; tc < tiles.tilesC; ++tc) {
    const auto [lo, hi] = tileWindow(tc, layout.nc, 0);
    cells.reset(layout.nb);
    for (int c = lo; c <= hi; ++c) cells.addLine(layout, c);
    wide = cells;
    if (lo > 0) wide.addLine(layout, lo - 1);
    if (hi < layout.nc - 1) wide.addLine(layout, hi + 1);
    for (int tb = 0; tb < tiles.tilesB; ++tb) {
      const std::size_t n = std::size_t(tc) * tiles.tilesB + tb;
      scratch.cellTiles[n] = cells.over(tileWindow(tb, layout.nb, 0));
      scratch.wideTiles[n] = wide.over(tileWindow(tb, layout.nb, 1));
    }
  }
  pack(tiles, slice, scratch.cellTiles, tiles.cells);
  pack(tiles, slice, scratch.wideTiles, tiles.wide);
}

// Where the voxels of a slice are read: in the volume, or in a buffer of the worker's.
using SliceSource = std::function<SliceLayout(int slice, std::vector<Voxel>& buffer)>;

// Summarises `slices` (indices along the axis) into the allocated ranges of `tiles`.
template <class Summary>
void summariseSlices(const SliceSource& source, SliceTiles& tiles, const std::vector<int>& slices,
                     const std::function<void(double)>& progress) {
  std::mutex reporting;  // progress is called one at a time, with growing fractions
  std::size_t slicesDone = 0;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, slices.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      SliceScratch<Summary> scratch;
                      std::vector<Voxel> buffer;
                      for (std::size_t n = range.begin(); n != range.end(); ++n)
                        summariseSlice(source(slices[n], buffer), tiles, slices[n], scratch);
                      if (!progress) return;
                      const std::lock_guard<std::mutex> lock(reporting);
                      slicesDone += range.size();
                      progress(double(slicesDone) / double(slices.size()));
                    });
}

void summariseSlices(const SliceSource& source, SliceTiles& tiles, const std::vector<int>& slices,
                     const std::function<void(double)>& progress = {}) {
  if (tiles.labelled) summariseSlices<LabelledSummary>(source, tiles, slices, progress);
  else summariseSlices<PlainSummary>(source, tiles, slices, progress);
}

SliceSource volumeSlices(const Volume& volume, const SliceTiles& tiles) {
  return [&](int slice, std::vector<Voxel>&) { return sliceLayout(volume, tiles, slice); };
}

// The label parts of ranges whose slices hold no label: no labelled voxel (an empty range in an
// empty group, as packSlice writes it) and only bit 0 (every tile has voxels).
// Filled in parallel, so that the threads touch the new pages (core/uninitialised_allocator.h).
void fillWithoutLabels(TileRanges& ranges) {
  const std::size_t count = ranges.unlabelled.minOffset.size();
  PackedRanges& labelled = ranges.labelled;
  labelled.minOffset.resize(count);
  labelled.maxOffset.resize(count);
  ranges.labelBits.resize(count);
  labelled.scale.assign(ranges.unlabelled.scale.size(), PackedRanges::Scale{});
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, count), [&](const tbb::blocked_range<std::size_t>& part) {
        const auto from = std::ptrdiff_t(part.begin()), to = std::ptrdiff_t(part.end());
        std::fill(labelled.minOffset.begin() + from, labelled.minOffset.begin() + to,
                  PackedRanges::kEmptyMin);
        std::fill(labelled.maxOffset.begin() + from, labelled.maxOffset.begin() + to,
                  PackedRanges::kEmptyMax);
        std::fill(ranges.labelBits.begin() + from, ranges.labelBits.begin() + to, std::uint16_t(1));
      });
}

void dropLabels(TileRanges& ranges) {
  ranges.labelled = {};
  ranges.labelBits = {};
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

// Whether a voxel of `slices` carries a label.
bool anyLabelIn(const Volume& volume, const SliceTiles& tiles, const std::vector<int>& slices) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, slices.size()), false,
      [&](const tbb::blocked_range<std::size_t>& range, bool found) {
        for (std::size_t n = range.begin(); n != range.end() && !found; ++n) {
          const SliceLayout slice = sliceLayout(volume, tiles, slices[n]);
          Voxel bits = 0;
          for (int c = 0; c < slice.nc; ++c)
            for (int b = 0; b < slice.nb; ++b)
              bits |= slice.first[c * slice.strideC + b * slice.strideB];
          found = labelOf(bits) != 0;
        }
        return found;
      },
      [](bool a, bool b) { return a || b; });
}

// Whether the tiles of a slice other than `slices` (ascending) know of a label.
bool anyLabelOutside(const SliceTiles& tiles, const std::vector<int>& slices) {
  if (!tiles.labelled) return false;
  const std::size_t perSlice = std::size_t(tiles.tilesPerSlice());
  auto stale = slices.begin();
  for (int slice = 0; slice < tiles.slices; ++slice) {
    if (stale != slices.end() && *stale == slice) {
      ++stale;
      continue;
    }
    const auto first = tiles.cells.labelBits.begin() + std::ptrdiff_t(slice * perSlice);
    if (std::any_of(first, first + std::ptrdiff_t(perSlice),
                    [](std::uint16_t bits) { return bits > 1; }))
      return true;
  }
  return false;
}

std::size_t bytesOf(const TileRanges& r) {
  return r.unlabelled.memoryBytes() + r.labelled.memoryBytes() +
         r.labelBits.size() * sizeof(std::uint16_t);
}

// Tiles of the volume's size about `axis`, allocated (with label parts if `labelled`), not filled.
SliceTiles allocatedTiles(const Volume& volume, Axis axis, bool labelled) {
  SliceTiles tiles;
  tiles.axis = axis;
  tiles.axisB = (int(axis) + 1) % 3;
  tiles.axisC = (int(axis) + 2) % 3;
  tiles.slices = volume.dims[int(axis)];
  tiles.tilesB = tilesAlong(volume.dims[tiles.axisB]);
  tiles.tilesC = tilesAlong(volume.dims[tiles.axisC]);
  tiles.labelled = labelled;
  allocate(tiles, tiles.cells);
  allocate(tiles, tiles.wide);
  return tiles;
}

std::vector<int> allSlices(const SliceTiles& tiles) {
  std::vector<int> slices(std::size_t(tiles.slices));
  std::iota(slices.begin(), slices.end(), 0);
  return slices;
}

}  // namespace

SliceTiles buildSliceTiles(const Volume& volume, Axis axis,
                           const std::function<void(double)>& progress) {
  SliceTiles tiles = allocatedTiles(volume, axis, anyLabel(volume));
  summariseSlices(volumeSlices(volume, tiles), tiles, allSlices(tiles), progress);
  return tiles;
}

SliceTiles unsummarisedSliceTiles(const Volume& volume, Axis axis, bool labelled) {
  return allocatedTiles(volume, axis, labelled);
}

void summariseSliceTiles(SliceTiles& tiles, const Volume& volume, const std::vector<int>& slices) {
  summariseSlices(volumeSlices(volume, tiles), tiles, slices);
}

bool summariseSliceTiles(SliceTiles& tiles, const Volume& volume, std::vector<int>& unbuilt,
                         const std::atomic<bool>* cancel, const std::function<void(double)>& progress) {
  const std::size_t sliceVoxels = std::size_t(volume.dims[tiles.axisB]) * volume.dims[tiles.axisC];
  std::size_t group =
      std::clamp<std::size_t>((std::size_t(1) << 20) / std::max<std::size_t>(sliceVoxels, 1), 2, 64);
  // Slices are shared out to the threads one each: a multiple of 2 or 4 keeps none idle.
  group = group < 4 ? (group + 1) / 2 * 2 : group / 4 * 4;
  while (!unbuilt.empty()) {
    if (cancel && cancel->load(std::memory_order_relaxed)) return false;
    const std::size_t count = std::min(group, unbuilt.size());
    const std::vector<int> slices(unbuilt.end() - std::ptrdiff_t(count), unbuilt.end());
    summariseSliceTiles(tiles, volume, slices);
    unbuilt.resize(unbuilt.size() - count);
    if (progress) progress(1.0 - double(unbuilt.size()) / double(std::max(tiles.slices, 1)));
  }
  return true;
}

bool volumeHasLabels(const Volume& volume) { return anyLabel(volume); }

bool overlaySummarisedAbout(Axis axis) { return axis != Axis::i; }

SliceTiles buildSliceTiles(const Volume& volume, Axis axis, const LabelOverlay& overlay,
                           const std::function<void(double)>& progress) {
  if (!overlaySummarisedAbout(axis))
    throw std::invalid_argument("buildSliceTiles: a label overlay is not summarised about i");
  const bool overlayLabels = std::any_of(overlay.labels.begin(), overlay.labels.end(),
                                         [](std::uint8_t label) { return label != 0; });
  SliceTiles tiles = allocatedTiles(volume, axis, overlayLabels || anyLabel(volume));
  const SliceSource source = [&](int slice, std::vector<Voxel>& buffer) {
    return overlaidSlice(volume, tiles, overlay, slice, buffer);
  };
  summariseSlices(source, tiles, allSlices(tiles), progress);
  // The overlay took the volume's last labels away: as a build of the volume without labels.
  if (tiles.labelled && !anyLabelOutside(tiles, {})) {
    tiles.labelled = false;
    dropLabels(tiles.cells);
    dropLabels(tiles.wide);
  }
  return tiles;
}

void refreshSliceTiles(SliceTiles& tiles, const Volume& volume, const std::vector<int>& slices) {
  if (slices.empty()) return;
  // The voxels outside `slices` are as the tiles know them: no need to read them.
  const bool labelled = anyLabelOutside(tiles, slices) || anyLabelIn(volume, tiles, slices);
  // A change between "no label anywhere" and "some label": the slices not refreshed hold no
  // label either way, so their density ranges stay and their label parts are the empty ones.
  if (labelled != tiles.labelled) {
    tiles.labelled = labelled;
    for (TileRanges* ranges : {&tiles.cells, &tiles.wide}) {
      if (labelled) fillWithoutLabels(*ranges);
      else dropLabels(*ranges);
    }
  }
  summariseSlices(volumeSlices(volume, tiles), tiles, slices);
}

std::vector<int> slicesHolding(const Volume& volume, Axis axis, const std::vector<std::size_t>& voxels) {
  const std::size_t along = strideAlong(volume, int(axis)), count = std::size_t(volume.dims[int(axis)]);
  std::vector<int> slices;
  if (axis == Axis::k) {  // the slices of ascending voxels ascend: one search per slice held
    for (auto voxel = voxels.begin(); voxel != voxels.end();
         voxel = std::lower_bound(voxel, voxels.end(), (std::size_t(slices.back()) + 1) * along))
      slices.push_back(int(*voxel / along));
    return slices;
  }
  std::vector<char> holds(count, 0);
  for (const std::size_t voxel : voxels) holds[voxel / along % count] = 1;
  for (std::size_t slice = 0; slice < count; ++slice)
    if (holds[slice]) slices.push_back(int(slice));
  return slices;
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
