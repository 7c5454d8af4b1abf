#pragma once
// Which slice tiles the TFs of a render can see. The integrated opacity table answers "is any
// density of the tile's range visible?" in O(1) per tile without reading voxels again (thesis sec.
// 4.2.2), so re-classifying after a TF change costs a pass over the tile ranges only. Labels
// (rendering model, "Labels") re-classify the same way: a tile's hidden labels read as density 0
// and its labels' own TFs count for the densities it holds (core/slice_tiles.h keeps which labels
// occur), so a hidden bone leaves no tile visible.
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
  // `mip`: also each tile's largest density as the labels read it, which MIP needs.
  // `recycle` (optional): a classification this one
  // replaces, whose memory it takes over (fresh memory costs page faults that would double a
  // re-classification's time).
  TileClassification(const SliceTiles& tiles, const RegionTables& tables, bool mip = false,
                     TileClassification* recycle = nullptr);
  TileClassification(const SliceTiles& tiles, const TfTable& table)
      : TileClassification(tiles, singleTable(table)) {}
  // It keeps a pointer to the tiles: temporary tiles would dangle.
  TileClassification(const SliceTiles&&, const RegionTables&, bool = false,
                     TileClassification* = nullptr) = delete;
  TileClassification(const SliceTiles&&, const TfTable&) = delete;

  const SliceTiles& tiles() const { return *tiles_; }
  Axis axis() const { return tiles_->axis; }
  // Which tiles may hold a visible sample, for the filter's reach (core/slice_tiles.h): one word
  // per slice and tile group, [slice * groupsPerSlice() + group], bit groupBit(tile) per tile.
  const std::vector<std::uint64_t>& visibleMasks(Filter filter) const {
    return filter == Filter::mean ? wideVisible_ : cellsVisible_;
  }
  std::size_t visibleTileCount(Filter filter) const;
  std::size_t memoryBytes() const;
  // Per tile, the largest density a sample of the filter's reach can read (MIP): hidden labels
  // read 0. Only if hasMaxima().
  const std::vector<std::uint16_t>& maxDensity(Filter filter) const;
  bool hasMaxima() const { return hasMaxima_; }
  // True iff made from these TF table objects (the regions themselves do not matter).
  bool classifies(const RegionTables& tables) const;

 private:
  struct UsedTables {
    const TfTable* focus = nullptr;
    const TfTable* context = nullptr;
    const TfTable* outside = nullptr;
    const LabelTables* labels = nullptr;
    friend bool operator==(const UsedTables&, const UsedTables&) = default;
  };
  static UsedTables usedBy(const RegionTables& tables);
  // read(ranges, n) tells what tile n's reach reads (as the labels say).
  template <bool Maxima, class ReadTile>
  void classify(ReadTile&& read, const TfTable& anyRegion, const LabelTables& labels);
  // The same as classify without maxima for a volume without labels, group by group.
  void classifyPlainGroups(const TfTable& anyRegion);
  // Sets the visibility bits of every tile: visible(n) gives the tile's {cells, wide} visibility.
  template <class TileVisible>
  void setMasks(TileVisible&& visible);

  const SliceTiles* tiles_;
  UsedTables tables_;
  bool hasMaxima_ = false;
  std::vector<std::uint64_t> cellsVisible_, wideVisible_;
  // With maxima only: per tile, the largest density a sample can read (as the labels read).
  std::vector<std::uint16_t> cellsMax_, wideMax_;
};

}  // namespace angio
