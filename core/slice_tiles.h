#pragma once
// Empty-space skipping structure for rotation about one axis (thesis sec. 4.3.3, flattened):
// with parallel projection every ray stays in the plane of one image row, perpendicular to the
// rotation axis a, so a row only ever reads the few slices around its own. Each slice is cut into
// kTileSize^2 tiles with the min/max density of every voxel a sample attributed to the tile can
// read. A sample belongs to the tile of its cell base f = min(floor(q), n - 2) (core/
// volume_sampling.h cellAt); nearest and trilinear read voxels f .. f + 1, so a tile's range is
// taken over the tile grown by one voxel after. The mean filter reads f - 1 .. f + 2, so a
// second range is kept over the tile grown by one more voxel on each side.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/render_params.h"
#include "core/transfer_function.h"
#include "core/uninitialised_allocator.h"
#include "core/volume.h"

namespace angio {

// 4^2-voxel tiles, half the thesis's 8^2: on CT with realistic noise and faint organs many 8^2
// tiles near the vessels touch the TF's ramp somewhere; 4^2 tiles evaluate about half as many
// samples (`angioray bench --profile`).
constexpr int kTileSize = 4;
// Tiles along an axis of `voxels` voxels (the last one may be partial).
constexpr int tilesAlong(int voxels) { return (voxels + kTileSize - 1) / kTileSize; }
// A tile group is kGroupTiles^2 tiles (32^2 voxels) of a slice: its tiles' visibility is one
// 64-bit word, so a ray tests all the tiles it crosses in a group at once.
constexpr int kGroupTiles = 8;
static_assert(kGroupTiles * kGroupTiles == 64);

// A tile of a slice: its index [slice][tileC][tileB] and its group's [slice][groupC][groupB].
struct TileRef {
  std::size_t tile = 0;
  std::size_t group = 0;
};

// One density range per tile, in a byte per end: offsets from the base of the tile's group, in
// steps of a power of two per group (block floating point). Exact where a group's tiles span
// fewer than 256 densities (soft tissue with its noise), rounded outwards (the minimum down, the
// maximum up) where they span more, so a stored range always holds the exact one: a tile
// classified invisible is invisible. 4^2 tiles in 16-bit ranges would need four times the memory
// of the thesis's 8^2.
struct PackedRanges {
  struct Scale {
    std::uint16_t base = 0;
    std::uint8_t shift = 0;
    std::uint8_t top = 0;  // the largest max offset of the group's tiles
  };
  static constexpr std::uint8_t kEmptyMin = 0xFF, kEmptyMax = 0;  // min > max: no voxel

  // Per tile; resized without zeroing (every tile is written when its slice is summarised).
  UninitialisedVector<std::uint8_t> minOffset;
  UninitialisedVector<std::uint8_t> maxOffset;
  std::vector<Scale> scale;  // per group

  // The tile's range; an empty one is [kDensityLevels, -1].
  int lowest(TileRef t) const {
    const Scale s = scale[t.group];
    return empty(t) ? kDensityLevels : s.base + (minOffset[t.tile] << s.shift);
  }
  int highest(TileRef t) const {
    const Scale s = scale[t.group];
    return empty(t) ? -1
                    : std::min(s.base + ((maxOffset[t.tile] + 1) << s.shift) - 1, kDensityLevels - 1);
  }
  bool empty(TileRef t) const { return minOffset[t.tile] > maxOffset[t.tile]; }
  // A range holding every tile range of group g (of a group without voxels: [0, 0]).
  int groupLowest(std::size_t g) const { return scale[g].base; }
  int groupHighest(std::size_t g) const {
    const Scale s = scale[g];
    return std::min(s.base + ((s.top + 1) << s.shift) - 1, kDensityLevels - 1);
  }
  std::size_t memoryBytes() const {
    return minOffset.size() + maxOffset.size() + scale.size() * sizeof(Scale);
  }
};

// What the voxels of one reach (a tile's cells, or the tile grown for the mean filter) hold, per
// tile. Labels decide how a voxel reads and which TF classifies it, so in a volume with labels the
// unlabelled and the labelled voxels keep separate ranges, and the labels that occur are kept as
// bits: a classification can then cut out hidden labels and use the labels' own TFs without
// reading a voxel again.
struct TileRanges {
  PackedRanges unlabelled;  // all voxels, without labels
  // Only for a volume with labels (empty otherwise):
  PackedRanges labelled;
  // Bit L: a voxel with label L occurs (bit 0: unlabelled).
  UninitialisedVector<std::uint16_t> labelBits;
};

struct SliceTiles {
  Axis axis = Axis::k;
  int axisB = 0, axisC = 1;  // the in-plane axes (b, c) of the rendering model
  int slices = 0;            // n_a
  int tilesB = 0, tilesC = 0;
  bool labelled = false;  // some voxel carries a label: the TileRanges' label parts are filled
  TileRanges cells;       // the voxels the tile's cells read (nearest, trilinear)
  TileRanges wide;        // the same grown by one voxel (mean filter)

  std::size_t tileCount() const { return cells.unlabelled.minOffset.size(); }
  const TileRanges& reach(Filter filter) const { return filter == Filter::mean ? wide : cells; }
  std::size_t memoryBytes() const;

  int tilesPerSlice() const { return tilesB * tilesC; }
  int groupsB() const { return (tilesB + kGroupTiles - 1) / kGroupTiles; }
  int groupsC() const { return (tilesC + kGroupTiles - 1) / kGroupTiles; }
  int groupsPerSlice() const { return groupsB() * groupsC(); }
  TileRef ref(int slice, int tileC, int tileB) const {
    return {std::size_t(slice) * tilesPerSlice() + std::size_t(tileC) * tilesB + tileB,
            std::size_t(slice) * groupsPerSlice() + std::size_t(tileC / kGroupTiles) * groupsB() +
                tileB / kGroupTiles};
  }
  int groupOf(int tile) const {
    return (tile / tilesB / kGroupTiles) * groupsB() + (tile % tilesB) / kGroupTiles;
  }
  // The tile's bit in its group's 64-bit masks: (tileC mod kGroupTiles, tileB mod kGroupTiles).
  int groupBit(int tile) const {
    return (tile / tilesB % kGroupTiles) * kGroupTiles + tile % tilesB % kGroupTiles;
  }
};

// The tiles of `volume` for rotation about `axis`. `progress`, if given, is called with the
// fraction of slices done, growing, one call at a time (from the building threads); an exception
// it throws stops the build and leaves this function (e.g. a load's cancel).
SliceTiles buildSliceTiles(const Volume& volume, Axis axis,
                           const std::function<void(double)>& progress = {});

// A build in parts, e.g. between a renderer's cancellation checks: the tiles allocated with no
// slice summarised yet; `labelled`: whether some voxel of the volume carries a label
// (volumeHasLabels). Once summariseSliceTiles has summarised every slice, the tiles equal
// buildSliceTiles(volume, axis).
SliceTiles unsummarisedSliceTiles(const Volume& volume, Axis axis, bool labelled);
void summariseSliceTiles(SliceTiles& tiles, const Volume& volume, const std::vector<int>& slices);
// Summarises the `unbuilt` slices (ascending; each taken out once done) in groups of some 1 M
// voxels (2-3 ms at 2 threads), until none is left (true) or `cancel` is set before a group
// (false). `progress`, if given, gets the fraction of all the tiles' slices summarised after each
// group.
bool summariseSliceTiles(SliceTiles& tiles, const Volume& volume, std::vector<int>& unbuilt,
                         const std::atomic<bool>* cancel,
                         const std::function<void(double)>& progress = {});
bool volumeHasLabels(const Volume& volume);

// Labels for some voxels, not yet written into the volume: a label change whose tiles are built
// ahead, while renderers still read the volume as it is.
struct LabelOverlay {
  const std::vector<std::size_t>& voxels;   // ascending indices into Volume::voxels
  const std::vector<std::uint8_t>& labels;  // the label of each
};

// Whether buildSliceTiles takes an overlay for `axis`: where a slice's voxels lie in runs along i
// (rotation about j or k); about i each voxel of a slice would be looked up alone.
bool overlaySummarisedAbout(Axis axis);

// buildSliceTiles of the volume as it will be once `overlay`'s labels are written, read from
// `volume` as it is (which is left alone). Needs overlaySummarisedAbout(axis).
SliceTiles buildSliceTiles(const Volume& volume, Axis axis, const LabelOverlay& overlay,
                           const std::function<void(double)>& progress = {});

// Summarises `slices` of `tiles` again from `volume`, whose voxels in no other slice changed since
// the tiles were built (e.g. a label change in those slices): the tiles are then equal to
// buildSliceTiles(volume, tiles.axis), in a time proportional to the slices refreshed.
void refreshSliceTiles(SliceTiles& tiles, const Volume& volume, const std::vector<int>& slices);

// The slices along `axis` that hold any of `voxels` (ascending indices into Volume::voxels),
// ascending.
std::vector<int> slicesHolding(const Volume& volume, Axis axis, const std::vector<std::size_t>& voxels);

// The cell base along one axis of n voxels: min(floor(clamp(q)), n - 2), as cellAt computes it.
int cellBase(double q, int n);

// The slices a row at axis coordinate qa (voxel units) reads with the filter: f .. f + 1 for
// nearest and trilinear, f - 1 .. f + 2 for mean (f = cellBase(qa)).
struct SliceSpan {
  int first = 0;
  int last = -1;
};
SliceSpan slicesReadAt(const SliceTiles& tiles, double qa, Filter filter);

}  // namespace angio
