#include "core/tile_classification.h"

#include <algorithm>
#include <bit>

#include <tbb/parallel_for.h>

namespace angio {

namespace {

// Which labels do what, as bit masks over the 16 labels (bit L for label L).
struct LabelMasks {
  std::uint16_t hidden = 0;  // read as density 0
  std::uint16_t own = 0;     // classified with their own TF

  explicit LabelMasks(const LabelTables& labels) {
    for (int label = 1; label < kLabelCount; ++label) {
      if (labels.hidden(label)) hidden |= std::uint16_t(1u << label);
      if (labels.ownTf(label)) own |= std::uint16_t(1u << label);
    }
  }
};

// The densities one reach of a tile reads as the labels say, and whether the region's TF
// classifies some of its samples. Empty ranges are [kDensityLevels, -1] (TileRanges), so the
// union of ranges is a min and a max without branches.
// Ints throughout: 16-bit fields written one by one and read back as a whole stall the loop.
struct TileReading {
  int lo = kDensityLevels, hi = -1;
  int regionTfs = 0;  // nonzero: some sample uses the region's TF
  int ownTfs = 0;     // the present labels with their own TF
};

// A tile of a volume without labels: its range, classified with the region's TF.
[[gnu::always_inline]] inline TileReading readPlainTile(const TileRanges& r, TileRef t) {
  return {r.unlabelled.lowest(t), r.unlabelled.highest(t), 1, 0};
}

// Inlined into the loop over millions of tiles: a call per tile costs more than its work.
[[gnu::always_inline]] inline TileReading readTile(const TileRanges& r, TileRef t,
                                                   const LabelMasks& masks) {
  const std::uint16_t bits = r.labelBits[t.tile];
  const std::uint16_t labelled = bits & ~1u;
  const std::uint16_t hidden = labelled & masks.hidden;
  const std::uint16_t shown = labelled & ~masks.hidden;  // read their own densities
  TileReading reading;
  reading.lo = r.unlabelled.lowest(t);
  reading.hi = r.unlabelled.highest(t);
  if (shown) {
    // The labelled range is shared by the tile's labels: wider than one label's, never narrower.
    reading.lo = std::min(reading.lo, r.labelled.lowest(t));
    reading.hi = std::max(reading.hi, r.labelled.highest(t));
  }
  if (hidden) {  // cut out: reads -1024 HU (density 0), classified with the region's TF
    reading.lo = 0;
    reading.hi = std::max(reading.hi, 0);
  }
  reading.ownTfs = shown & masks.own;
  reading.regionTfs = (bits & 1u) | hidden | (shown & ~masks.own);
  return reading;
}

[[gnu::always_inline]] inline bool isVisible(const TileReading& reading, const TfTable& anyRegion,
                                             const LabelTables& labels) {
  if (reading.regionTfs && anyRegion.anyVisible(reading.lo, reading.hi)) return true;
  for (unsigned rest = unsigned(reading.ownTfs); rest; rest &= rest - 1)
    if (labels.ownTf(std::countr_zero(rest))->anyVisible(reading.lo, reading.hi)) return true;
  return false;
}

// The visibility bits of one group's tiles in a volume without labels, under `table`. A group
// whose whole range the TF hides is answered by one query: at a vessel TF that is most groups of a
// CT, so a TF change costs about a query per group rather than one per tile. Empty tiles need no
// test of their own: their offsets (kEmptyMin > kEmptyMax) give lo > hi, which anyVisible refuses.
std::uint64_t plainGroupMask(const SliceTiles& t, const PackedRanges& r, std::size_t group,
                             std::size_t firstTile, int tileRows, int tileColumns,
                             const TfTable& table) {
  if (!table.anyVisible(r.groupLowest(group), r.groupHighest(group))) return 0;
  const PackedRanges::Scale s = r.scale[group];
  std::uint64_t mask = 0;
  for (int row = 0; row < tileRows; ++row) {
    const std::size_t first = firstTile + std::size_t(row) * t.tilesB;
    for (int column = 0; column < tileColumns; ++column) {
      const int lo = s.base + (r.minOffset[first + column] << s.shift);
      const int hi = s.base + ((r.maxOffset[first + column] + 1) << s.shift) - 1;
      mask |= std::uint64_t(table.anyVisible(lo, hi)) << (row * kGroupTiles + column);
    }
  }
  return mask;
}

struct TileVisibility {
  bool cells = false;  // for the tile's cells (nearest, trilinear)
  bool wide = false;   // for the tile grown by one voxel (mean)
};

// The largest density a sample can read (0 for an empty reading).
std::uint16_t largestDensity(const TileReading& reading) {
  return std::uint16_t(reading.lo <= reading.hi ? reading.hi : 0);
}

}  // namespace

TileClassification::UsedTables TileClassification::usedBy(const RegionTables& tables) {
  const bool regions = tables.regions != nullptr;
  return {regions ? tables.focus : nullptr, regions ? tables.context : nullptr, tables.outside,
          tables.labels};
}

TileClassification::TileClassification(const SliceTiles& tiles, const RegionTables& tables, bool mip,
                                       TileClassification* recycle)
    : tiles_(&tiles), tables_(usedBy(tables)), hasMaxima_(mip) {
  if (recycle) {
    cellsVisible_ = std::move(recycle->cellsVisible_);
    wideVisible_ = std::move(recycle->wideVisible_);
    cellsMax_ = std::move(recycle->cellsMax_);
    wideMax_ = std::move(recycle->wideMax_);
  }
  const TfTable anyRegion = visibilityUnion({tables_.focus, tables_.context, tables_.outside});
  const LabelTables noLabels;
  const LabelTables& labels = tables.labels ? *tables.labels : noLabels;
  if (tiles.labelled) {
    const LabelMasks masks(labels);
    const auto read = [&](const TileRanges& r, TileRef t) { return readTile(r, t, masks); };
    if (mip) classify<true>(read, anyRegion, labels);
    else classify<false>(read, anyRegion, labels);
  } else {
    if (mip) classify<true>(readPlainTile, anyRegion, labels);
    else classifyPlainGroups(anyRegion);
  }
}

void TileClassification::classifyPlainGroups(const TfTable& anyRegion) {
  const SliceTiles& t = *tiles_;
  const std::size_t groups = t.groupsPerSlice();
  cellsMax_ = {}, wideMax_ = {};
  cellsVisible_.resize(groups * t.slices);
  wideVisible_.resize(groups * t.slices);
  tbb::parallel_for(0, t.slices, [&](int slice) {
    for (int gc = 0; gc < t.groupsC(); ++gc)
      for (int gb = 0; gb < t.groupsB(); ++gb) {
        const TileRef first = t.ref(slice, gc * kGroupTiles, gb * kGroupTiles);
        const int rows = std::min(kGroupTiles, t.tilesC - gc * kGroupTiles);
        const int columns = std::min(kGroupTiles, t.tilesB - gb * kGroupTiles);
        cellsVisible_[first.group] =
            plainGroupMask(t, t.cells.unlabelled, first.group, first.tile, rows, columns, anyRegion);
        wideVisible_[first.group] =
            plainGroupMask(t, t.wide.unlabelled, first.group, first.tile, rows, columns, anyRegion);
      }
  });
}

template <bool Maxima, class ReadTile>
void TileClassification::classify(ReadTile&& read, const TfTable& anyRegion, const LabelTables& labels) {
  const TileRanges &cells = tiles_->cells, &wide = tiles_->wide;
  if (Maxima) cellsMax_.resize(tiles_->tileCount()), wideMax_.resize(tiles_->tileCount());
  else cellsMax_ = {}, wideMax_ = {};
  setMasks([&](TileRef t) {
    const TileReading cellReading = read(cells, t);
    const TileReading wideReading = read(wide, t);
    if constexpr (Maxima) {
      cellsMax_[t.tile] = largestDensity(cellReading);
      wideMax_[t.tile] = largestDensity(wideReading);
    }
    return TileVisibility{isVisible(cellReading, anyRegion, labels),
                          isVisible(wideReading, anyRegion, labels)};
  });
}

// Slice by slice, each tile's bits into its group's words (the groups of a slice are its own).
template <class ClassifyTile>
void TileClassification::setMasks(ClassifyTile&& classify) {
  const SliceTiles& t = *tiles_;
  const std::size_t groups = t.groupsPerSlice();
  cellsVisible_.assign(groups * t.slices, 0);
  wideVisible_.assign(groups * t.slices, 0);
  tbb::parallel_for(0, t.slices, [&](int slice) {
    std::uint64_t* cells = cellsVisible_.data() + groups * slice;
    std::uint64_t* wide = wideVisible_.data() + groups * slice;
    for (int tc = 0; tc < t.tilesC; ++tc) {
      std::uint64_t* cellsRow = cells + std::size_t(tc / kGroupTiles) * t.groupsB();
      std::uint64_t* wideRow = wide + std::size_t(tc / kGroupTiles) * t.groupsB();
      for (int tb = 0; tb < t.tilesB; ++tb) {
        const TileVisibility v = classify(t.ref(slice, tc, tb));
        const int bit = (tc % kGroupTiles) * kGroupTiles + tb % kGroupTiles;
        cellsRow[tb / kGroupTiles] |= std::uint64_t(v.cells) << bit;
        wideRow[tb / kGroupTiles] |= std::uint64_t(v.wide) << bit;
      }
    }
  });
}

std::size_t TileClassification::visibleTileCount(Filter filter) const {
  std::size_t count = 0;
  for (const std::uint64_t word : visibleMasks(filter)) count += std::popcount(word);
  return count;
}

std::size_t TileClassification::memoryBytes() const {
  return (cellsVisible_.size() + wideVisible_.size()) * sizeof(std::uint64_t) +
         (cellsMax_.size() + wideMax_.size()) * sizeof(std::uint16_t);
}

const std::vector<std::uint16_t>& TileClassification::maxDensity(Filter filter) const {
  return filter == Filter::mean ? wideMax_ : cellsMax_;
}

bool TileClassification::classifies(const RegionTables& tables) const {
  return usedBy(tables) == tables_;
}

}  // namespace angio
