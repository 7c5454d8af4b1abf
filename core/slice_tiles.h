#pragma once
// Empty-space skipping structure for rotation about one axis (thesis sec. 4.3.3, flattened):
// with parallel projection every ray stays in the plane of one image row, perpendicular to the
// rotation axis a, so a row only ever reads the few slices around its own. Each slice is cut into
// kTileSize^2 tiles with the min/max density of every voxel a sample attributed to the tile can
// read: a sample whose floor(q) lies in the tile reads voxels floor(q) - 1 .. floor(q) + 2 (the
// mean filter's reach), so the range is taken over the tile grown by 1 voxel before, 2 after.
#include <cstdint>
#include <vector>

#include "core/render_params.h"
#include "core/transfer_function.h"
#include "core/volume.h"

namespace angio {

constexpr int kTileSize = 8;
constexpr int kGroupTiles = 4;  // a tile group is kGroupTiles^2 tiles (32^2 voxels) of a slice

struct SliceTiles {
  Axis axis = Axis::k;
  int axisB = 0, axisC = 1;  // the in-plane axes (b, c) of the rendering model
  int slices = 0;            // n_a
  int tilesB = 0, tilesC = 0;
  std::vector<std::uint16_t> minDensity;  // [slice][tileC][tileB]
  std::vector<std::uint16_t> maxDensity;

  int tilesPerSlice() const { return tilesB * tilesC; }
  int groupsB() const { return (tilesB + kGroupTiles - 1) / kGroupTiles; }
  int groupsC() const { return (tilesC + kGroupTiles - 1) / kGroupTiles; }
  int groupOf(int tile) const {
    return (tile / tilesB / kGroupTiles) * groupsB() + (tile % tilesB) / kGroupTiles;
  }
};

SliceTiles buildSliceTiles(const Volume& volume, Axis axis);

// The slices a row at axis coordinate qa (voxel units) reads: floor(qa) - 1 .. floor(qa) + 2.
struct SliceSpan {
  int first = 0;
  int last = -1;
};
SliceSpan slicesReadAt(const SliceTiles& tiles, double qa);

// Per TF: which tiles of which slices hold a visible density (one byte per tile). Re-classifying
// is a table lookup per tile, no voxel is read again.
std::vector<std::uint8_t> classifyTiles(const SliceTiles& tiles, const TfTable& table);

}  // namespace angio
