#pragma once
// Empty-space skipping structure for rotation about one axis (thesis sec. 4.3.3, flattened):
// with parallel projection every ray stays in the plane of one image row, perpendicular to the
// rotation axis a, so a row only ever reads the few slices around its own. Each slice is cut into
// kTileSize^2 tiles with the min/max density of every voxel a sample attributed to the tile can
// read. A sample belongs to the tile of its cell base f = min(floor(q), n - 2) (core/
// volume_sampling.h cellAt); nearest and trilinear read voxels f .. f + 1, so a tile's range is
// taken over the tile grown by one voxel after. The mean filter reads f - 1 .. f + 2, so a
// second range is kept over the tile grown by one more voxel on each side.
#include <cstdint>
#include <vector>

#include "core/render_params.h"
#include "core/transfer_function.h"
#include "core/volume.h"

namespace angio {

constexpr int kTileSize = 8;
constexpr int kGroupTiles = 4;  // a tile group is kGroupTiles^2 tiles (32^2 voxels) of a slice

// What the voxels of one reach (a tile's cells, or the tile grown for the mean filter) hold, per
// tile [slice][tileC][tileB]. Labels decide how a voxel reads and which TF classifies it, so in a
// volume with labels the unlabelled and the labelled voxels keep separate ranges, and the labels
// that occur are kept as bits: a classification can then cut out hidden labels and use the labels'
// own TFs without reading a voxel again. An empty range has min > max.
struct TileRanges {
  std::vector<std::uint16_t> minDensity;  // over the unlabelled voxels (all, without labels)
  std::vector<std::uint16_t> maxDensity;
  // Only for a volume with labels (empty otherwise):
  std::vector<std::uint16_t> labelledMin;  // over the labelled voxels
  std::vector<std::uint16_t> labelledMax;
  std::vector<std::uint16_t> labelBits;  // bit L: a voxel with label L occurs (bit 0: unlabelled)
};

struct SliceTiles {
  Axis axis = Axis::k;
  int axisB = 0, axisC = 1;  // the in-plane axes (b, c) of the rendering model
  int slices = 0;            // n_a
  int tilesB = 0, tilesC = 0;
  bool labelled = false;  // some voxel carries a label: the TileRanges' label parts are filled
  TileRanges cells;       // the voxels the tile's cells read (nearest, trilinear)
  TileRanges wide;        // the same grown by one voxel (mean filter)

  std::size_t tileCount() const { return cells.minDensity.size(); }
  const TileRanges& reach(Filter filter) const { return filter == Filter::mean ? wide : cells; }
  std::size_t memoryBytes() const;

  int tilesPerSlice() const { return tilesB * tilesC; }
  int groupsB() const { return (tilesB + kGroupTiles - 1) / kGroupTiles; }
  int groupsC() const { return (tilesC + kGroupTiles - 1) / kGroupTiles; }
  int groupOf(int tile) const {
    return (tile / tilesB / kGroupTiles) * groupsB() + (tile % tilesB) / kGroupTiles;
  }
};

SliceTiles buildSliceTiles(const Volume& volume, Axis axis);

// The cell base along one axis of n voxels: min(floor(clamp(q)), n - 2), as cellAt computes it.
int cellBase(double q, int n);

// The slices a row at axis coordinate qa (voxel units) reads with the filter: f .. f + 1 for
// nearest and trilinear, f - 1 .. f + 2 for mean (f = cellBase(qa)).
struct SliceSpan {
  int first = 0;
  int last = -1;
};
SliceSpan slicesReadAt(const SliceTiles& tiles, double qa, Filter filter);

// A classification (core/tile_classification.h) keeps one byte per tile with two bits:
// kCellsVisible for the tile's own reach, kWideVisible for the grown one.
constexpr std::uint8_t kCellsVisible = 1;
constexpr std::uint8_t kWideVisible = 2;
// The bit that matters for a filter's reach.
constexpr std::uint8_t visibilityBit(Filter filter) {
  return filter == Filter::mean ? kWideVisible : kCellsVisible;
}

}  // namespace angio
