#include "core/tile_classification.h"

namespace angio {

TileClassification::UsedTables TileClassification::usedBy(const RegionTables& tables) {
  const bool regions = tables.regions != nullptr;
  return {regions ? tables.focus : nullptr, regions ? tables.context : nullptr, tables.outside};
}

TileClassification::TileClassification(const SliceTiles& tiles, const RegionTables& tables)
    : tiles_(&tiles), tables_(usedBy(tables)), visible_(tiles.minDensity.size(), 0) {
  for (const TfTable* table : {tables_.focus, tables_.context, tables_.outside}) {
    if (!table) continue;
    const std::vector<std::uint8_t> byTable = classifyTiles(tiles, *table);
    for (std::size_t n = 0; n < visible_.size(); ++n) visible_[n] |= byTable[n];
  }
}

bool TileClassification::classifies(const RegionTables& tables) const {
  return usedBy(tables) == tables_;
}

}  // namespace angio
