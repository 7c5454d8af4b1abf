#pragma once
// Which slice tiles the TFs of a render can see. The integrated opacity table answers "is any
// density of the tile's range visible?" in O(1) per tile without reading voxels again (thesis sec.
// 4.2.2), so re-classifying after a TF change costs a pass over the tile ranges only.
// A classification is made from one SliceTiles and the TF tables together and remembers both: a
// raycaster handed one can check that it belongs to the view's axis and to the TFs it renders
// with, instead of trusting its callers to pass matching pieces.
#include <cstdint>
#include <vector>

#include "core/compositing.h"
#include "core/slice_tiles.h"

namespace angio {

class TileClassification {
 public:
  // A tile is visible if any TF of `tables` shows a density in it (focus and context count only
  // with regions, as the raycaster renders them). `tiles` and the tables must outlive this.
  TileClassification(const SliceTiles& tiles, const RegionTables& tables);
  TileClassification(const SliceTiles& tiles, const TfTable& table)
      : TileClassification(tiles, singleTable(table)) {}

  const SliceTiles& tiles() const { return *tiles_; }
  Axis axis() const { return tiles_->axis; }
  // One byte per tile: kCellsVisible and kWideVisible (core/slice_tiles.h).
  const std::vector<std::uint8_t>& visible() const { return visible_; }
  // True iff made from these TF table objects (the regions themselves do not matter).
  bool classifies(const RegionTables& tables) const;

 private:
  struct UsedTables {
    const TfTable* focus = nullptr;
    const TfTable* context = nullptr;
    const TfTable* outside = nullptr;
    friend bool operator==(const UsedTables&, const UsedTables&) = default;
  };
  static UsedTables usedBy(const RegionTables& tables);

  const SliceTiles* tiles_;
  UsedTables tables_;
  std::vector<std::uint8_t> visible_;
};

}  // namespace angio
