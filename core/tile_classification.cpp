#include "core/tile_classification.h"

#include <algorithm>
#include <bit>

#include <tbb/parallel_for.h>

namespace angio {

namespace {

// The densities a reach of one tile reads as the labels say, and the TFs that classify them.
struct TileReading {
  int lo = 0xFFFF, hi = -1;  // empty: lo > hi
  bool regionTfs = false;    // some sample may use the region's TF
  std::uint16_t ownTfs = 0;  // labels whose own TF some sample may use

  void include(int min, int max) { lo = std::min(lo, min), hi = std::max(hi, max); }
};

TileReading readTile(const TileRanges& r, std::size_t n, const LabelTables& labels) {
  TileReading reading;
  const std::uint16_t bits = r.labelBits[n];
  if (bits & 1u) reading.include(r.minDensity[n], r.maxDensity[n]), reading.regionTfs = true;
  for (std::uint16_t rest = bits & ~1u; rest; rest &= rest - 1) {
    const int label = std::countr_zero(rest);
    if (labels.hidden(label)) {
      reading.include(0, 0);  // cut out: reads -1024 HU, classified with the region's TF
      reading.regionTfs = true;
      continue;
    }
    // The labelled range is shared by the tile's labels: wider than one label's, never narrower.
    reading.include(r.labelledMin[n], r.labelledMax[n]);
    if (labels.ownTf(label)) reading.ownTfs |= std::uint16_t(1u << label);
    else reading.regionTfs = true;
  }
  return reading;
}

bool isVisible(const TileReading& reading, const TfTable& anyRegion, const LabelTables& labels) {
  if (reading.regionTfs && anyRegion.anyVisible(reading.lo, reading.hi)) return true;
  for (std::uint16_t rest = reading.ownTfs; rest; rest &= rest - 1)
    if (labels.ownTf(std::countr_zero(rest))->anyVisible(reading.lo, reading.hi)) return true;
  return false;
}

std::uint16_t largestDensity(const TileReading& reading) {
  return std::uint16_t(std::max(reading.hi, 0));
}

}  // namespace

TileClassification::UsedTables TileClassification::usedBy(const RegionTables& tables) {
  const bool regions = tables.regions != nullptr;
  return {regions ? tables.focus : nullptr, regions ? tables.context : nullptr, tables.outside,
          tables.labels};
}

TileClassification::TileClassification(const SliceTiles& tiles, const RegionTables& tables)
    : tiles_(&tiles), tables_(usedBy(tables)), visible_(tiles.tileCount(), 0) {
  const TfTable anyRegion = visibilityUnion({tables_.focus, tables_.context, tables_.outside});
  if (tiles.labelled) {
    classifyLabelled(anyRegion, tables.labels ? *tables.labels : LabelTables());
    return;
  }
  const TileRanges &cells = tiles.cells, &wide = tiles.wide;
  tbb::parallel_for(std::size_t(0), visible_.size(), [&](std::size_t n) {
    visible_[n] = std::uint8_t(
        (anyRegion.anyVisible(cells.minDensity[n], cells.maxDensity[n]) ? kCellsVisible : 0) |
        (anyRegion.anyVisible(wide.minDensity[n], wide.maxDensity[n]) ? kWideVisible : 0));
  });
}

void TileClassification::classifyLabelled(const TfTable& anyRegion, const LabelTables& labels) {
  const TileRanges &cells = tiles_->cells, &wide = tiles_->wide;
  cellsMax_.resize(visible_.size());
  wideMax_.resize(visible_.size());
  tbb::parallel_for(std::size_t(0), visible_.size(), [&](std::size_t n) {
    const TileReading cellReading = readTile(cells, n, labels);
    const TileReading wideReading = readTile(wide, n, labels);
    visible_[n] = std::uint8_t((isVisible(cellReading, anyRegion, labels) ? kCellsVisible : 0) |
                               (isVisible(wideReading, anyRegion, labels) ? kWideVisible : 0));
    cellsMax_[n] = largestDensity(cellReading);
    wideMax_[n] = largestDensity(wideReading);
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
