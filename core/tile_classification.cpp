#include "core/tile_classification.h"

#include <algorithm>
#include <bit>

#include <tbb/blocked_range.h>
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
// classifies some of its samples. Empty ranges are stored as [0xFFFF, 0], so the union of ranges
// is a min and a max without branches.
// Ints throughout: 16-bit fields written one by one and read back as a whole stall the loop.
struct TileReading {
  int lo = 0xFFFF, hi = 0;
  int regionTfs = 0;  // nonzero: some sample uses the region's TF
  int ownTfs = 0;     // the present labels with their own TF
};

// Inlined into the loop over millions of tiles: a call per tile costs more than its work.
[[gnu::always_inline]] inline TileReading readTile(const TileRanges& r, std::size_t n,
                                                   const LabelMasks& masks) {
  const std::uint16_t bits = r.labelBits[n];
  const std::uint16_t labelled = bits & ~1u;
  const std::uint16_t hidden = labelled & masks.hidden;
  const std::uint16_t shown = labelled & ~masks.hidden;  // read their own densities
  TileReading reading;
  reading.lo = r.minDensity[n];
  reading.hi = r.maxDensity[n];
  if (shown) {
    // The labelled range is shared by the tile's labels: wider than one label's, never narrower.
    reading.lo = std::min<int>(reading.lo, r.labelledMin[n]);
    reading.hi = std::max<int>(reading.hi, r.labelledMax[n]);
  }
  if (hidden) reading.lo = 0;  // cut out: reads -1024 HU, classified with the region's TF
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
    : tiles_(&tiles), tables_(usedBy(tables)) {
  if (recycle) {
    visible_ = std::move(recycle->visible_);
    cellsMax_ = std::move(recycle->cellsMax_);
    wideMax_ = std::move(recycle->wideMax_);
  }
  visible_.resize(tiles.tileCount());  // every entry is written below
  if (!tiles.labelled || !mip) cellsMax_ = {}, wideMax_ = {};
  const TfTable anyRegion = visibilityUnion({tables_.focus, tables_.context, tables_.outside});
  if (tiles.labelled) {
    const LabelTables& labels = tables.labels ? *tables.labels : LabelTables();
    if (mip) classifyLabelled<true>(anyRegion, labels);
    else classifyLabelled<false>(anyRegion, labels);
    return;
  }
  const TileRanges &cells = tiles.cells, &wide = tiles.wide;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, visible_.size(), 1 << 14),
      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t n = range.begin(); n != range.end(); ++n)
          visible_[n] = std::uint8_t(
              (anyRegion.anyVisible(cells.minDensity[n], cells.maxDensity[n]) ? kCellsVisible : 0) |
              (anyRegion.anyVisible(wide.minDensity[n], wide.maxDensity[n]) ? kWideVisible : 0));
      });
}

template <bool Maxima>
void TileClassification::classifyLabelled(const TfTable& anyRegion, const LabelTables& labels) {
  const TileRanges &cells = tiles_->cells, &wide = tiles_->wide;
  if (Maxima) cellsMax_.resize(visible_.size()), wideMax_.resize(visible_.size());
  const LabelMasks masks(labels);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, visible_.size(), 1 << 14),
      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t n = range.begin(); n != range.end(); ++n) {
          const TileReading cellReading = readTile(cells, n, masks);
          const TileReading wideReading = readTile(wide, n, masks);
          visible_[n] = std::uint8_t((isVisible(cellReading, anyRegion, labels) ? kCellsVisible : 0) |
                                     (isVisible(wideReading, anyRegion, labels) ? kWideVisible : 0));
          if constexpr (Maxima) {
            cellsMax_[n] = largestDensity(cellReading);
            wideMax_[n] = largestDensity(wideReading);
          }
        }
      });
}

const std::vector<std::uint16_t>& TileClassification::maxDensity(Filter filter) const {
  const bool wide = filter == Filter::mean;
  if (tiles_->labelled) return wide ? wideMax_ : cellsMax_;
  return tiles_->reach(filter).maxDensity;
}

bool TileClassification::classifies(const RegionTables& tables) const {
  return usedBy(tables) == tables_;
}

}  // namespace angio
