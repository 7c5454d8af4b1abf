// Slice tiles keep their density ranges packed (a byte per end, per-group scale) and a TF change
// classifies a volume without labels group by group. Both are checked against ranges computed
// here straight from the voxels: a packed range must hold the exact one (and equal it where the
// group's densities span less than a byte), a tile with a visible exact range must be classified
// visible, and the group-by-group classification must equal the tile-by-tile one.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/tile_classification.h"
#include "phantom/phantom.h"

namespace angio {
namespace {

struct ExactRange {
  int lo = kDensityLevels, hi = -1;
};

// Calls visit(voxel) for the voxels tile (tb, tc) of `slice` reads, grown by `reach` voxels (0: cells,
// 1: mean filter).
template <class Visit>
void forEachVoxelOfTile(const Volume& volume, const SliceTiles& t, int slice, int tc, int tb, int reach,
                        Visit&& visit) {
  const int nb = volume.dims[t.axisB], nc = volume.dims[t.axisC];
  for (int c = std::max(tc * kTileSize - reach, 0);
       c <= std::min(tc * kTileSize + kTileSize + reach, nc - 1); ++c)
    for (int b = std::max(tb * kTileSize - reach, 0);
         b <= std::min(tb * kTileSize + kTileSize + reach, nb - 1); ++b) {
      glm::ivec3 v;
      v[int(t.axis)] = slice;
      v[t.axisB] = b;
      v[t.axisC] = c;
      visit(volume.voxels[volume.indexOf(v.x, v.y, v.z)]);
    }
}

ExactRange exactRange(const Volume& volume, const SliceTiles& t, int slice, int tc, int tb, int reach) {
  ExactRange r;
  forEachVoxelOfTile(volume, t, slice, tc, tb, reach, [&](Voxel voxel) {
    r.lo = std::min(r.lo, densityOf(voxel));
    r.hi = std::max(r.hi, densityOf(voxel));
  });
  return r;
}

bool visibleBit(const TileClassification& c, Filter filter, const SliceTiles& t, int slice, int tc,
                int tb) {
  const TileRef ref = t.ref(slice, tc, tb);
  const int bit = (tc % kGroupTiles) * kGroupTiles + tb % kGroupTiles;
  return (c.visibleMasks(filter)[ref.group] >> bit) & 1u;
}

// Visible only at densities [d, d + 2]: one packed step too many either way shows up.
TransferFunction spike(int density) {
  const double hu = density - 1024;
  TransferFunction tf;
  tf.points = {{hu - 0.5, glm::vec3(1.f), 0},
               {hu, glm::vec3(1.f), 1},
               {hu + 2, glm::vec3(1.f), 1},
               {hu + 2.5, glm::vec3(1.f), 0}};
  return tf;
}

// 37 x 29 voxels per slice: ten by eight tiles, two groups along b, ragged edges. Left half soft
// tissue with noise (a group spanning fewer than 256 densities: packed exactly), right half the
// whole density scale (rounded to steps of 16).
Volume mixedVolume() {
  Volume volume = makeVolume({37, 29, 5}, glm::dvec3(1.0));
  std::mt19937 random(7);
  std::uniform_int_distribution<int> soft(1000, 1200), any(0, kDensityLevels - 1);
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 29; ++j)
      for (int i = 0; i < 37; ++i)
        volume.voxels[volume.indexOf(i, j, k)] =
            encodeVoxel((i < 32 ? soft(random) : any(random)) - 1024);
  return volume;
}

void checkTiles(const Volume& volume, Axis axis, const std::vector<int>& spikes) {
  const SliceTiles t = buildSliceTiles(volume, axis);
  for (int slice = 0; slice < t.slices; ++slice)
    for (int tc = 0; tc < t.tilesC; ++tc)
      for (int tb = 0; tb < t.tilesB; ++tb)
        for (const int reach : {0, 1}) {
          const PackedRanges& packed = (reach ? t.wide : t.cells).unlabelled;
          const TileRef ref = t.ref(slice, tc, tb);
          const ExactRange exact = exactRange(volume, t, slice, tc, tb, reach);
          ASSERT_LE(packed.lowest(ref), exact.lo) << slice << " " << tc << " " << tb;
          ASSERT_GE(packed.highest(ref), exact.hi) << slice << " " << tc << " " << tb;
          if (packed.scale[ref.group].shift == 0) {
            EXPECT_EQ(packed.lowest(ref), exact.lo);
            EXPECT_EQ(packed.highest(ref), exact.hi);
          }
          ASSERT_LE(packed.groupLowest(ref.group), packed.lowest(ref));
          ASSERT_GE(packed.groupHighest(ref.group), packed.highest(ref));
        }
  for (const int density : spikes) {
    const TfTable table = buildTable(spike(density));
    const TileClassification byGroup(t, singleTable(table));
    const TileClassification byTile(t, singleTable(table), /*mip=*/true);  // per tile, with maxima
    EXPECT_EQ(byGroup.visibleMasks(Filter::trilinear), byTile.visibleMasks(Filter::trilinear))
        << density;
    EXPECT_EQ(byGroup.visibleMasks(Filter::mean), byTile.visibleMasks(Filter::mean)) << density;
    for (int slice = 0; slice < t.slices; ++slice)
      for (int tc = 0; tc < t.tilesC; ++tc)
        for (int tb = 0; tb < t.tilesB; ++tb) {
          const ExactRange cells = exactRange(volume, t, slice, tc, tb, 0);
          const ExactRange wide = exactRange(volume, t, slice, tc, tb, 1);
          if (table.anyVisible(cells.lo, cells.hi))
            ASSERT_TRUE(visibleBit(byGroup, Filter::trilinear, t, slice, tc, tb)) << density;
          if (table.anyVisible(wide.lo, wide.hi))
            ASSERT_TRUE(visibleBit(byGroup, Filter::mean, t, slice, tc, tb)) << density;
        }
  }
}

// With labels: per tile the unlabelled and the labelled voxels' exact ranges and the labels that
// occur (bit L for label L, bit 0 for unlabelled voxels).
struct ExactLabelledTile {
  ExactRange unlabelled, labelled;
  std::uint16_t bits = 0;
};

ExactLabelledTile exactLabelledTile(const Volume& volume, const SliceTiles& t, int slice, int tc, int tb,
                                    int reach) {
  ExactLabelledTile tile;
  forEachVoxelOfTile(volume, t, slice, tc, tb, reach, [&](Voxel voxel) {
    ExactRange& range = labelOf(voxel) == 0 ? tile.unlabelled : tile.labelled;
    range.lo = std::min(range.lo, densityOf(voxel));
    range.hi = std::max(range.hi, densityOf(voxel));
    tile.bits |= std::uint16_t(1u << labelOf(voxel));
  });
  return tile;
}

void expectHolds(const PackedRanges& packed, TileRef ref, const ExactRange& exact) {
  if (exact.lo > exact.hi) {
    EXPECT_TRUE(packed.empty(ref));
    return;
  }
  EXPECT_LE(packed.lowest(ref), exact.lo);
  EXPECT_GE(packed.highest(ref), exact.hi);
  if (packed.scale[ref.group].shift == 0) {
    EXPECT_EQ(packed.lowest(ref), exact.lo);
    EXPECT_EQ(packed.highest(ref), exact.hi);
  }
}

// Labels in some lines only (most lines of a scan hold none), several labels in a line, a label
// everywhere in the last slice: the tiles keep both ranges and the labels exactly as the voxels are.
TEST(TileClassification, LabelledTilesHoldTheExactRangesOfBothKindsAndTheirLabels) {
  Volume volume = mixedVolume();
  std::mt19937 random(11);
  std::uniform_int_distribution<int> label(1, kMaxLabel);
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 29; ++j)
      for (int i = 0; i < 37; ++i) {
        Voxel& v = volume.voxels[volume.indexOf(i, j, k)];
        const bool labelled = k == 4 || (j % 7 == 3 && (i + k) % 3 == 0) || (i == 20 && j > 10);
        if (labelled) v = Voxel(densityOf(v) | label(random) << 12);
      }
  for (const Axis axis : {Axis::k, Axis::j, Axis::i}) {
    const SliceTiles t = buildSliceTiles(volume, axis);
    ASSERT_TRUE(t.labelled);
    for (int slice = 0; slice < t.slices; ++slice)
      for (int tc = 0; tc < t.tilesC; ++tc)
        for (int tb = 0; tb < t.tilesB; ++tb)
          for (const int reach : {0, 1}) {
            SCOPED_TRACE(testing::Message() << "axis " << int(axis) << " slice " << slice << " tile "
                                            << tc << "," << tb << " reach " << reach);
            const TileRanges& ranges = reach ? t.wide : t.cells;
            const TileRef ref = t.ref(slice, tc, tb);
            const ExactLabelledTile exact = exactLabelledTile(volume, t, slice, tc, tb, reach);
            expectHolds(ranges.unlabelled, ref, exact.unlabelled);
            expectHolds(ranges.labelled, ref, exact.labelled);
            EXPECT_EQ(ranges.labelBits[ref.tile], exact.bits);
          }
  }
}

TEST(TileClassification, PackedRangesHoldTheExactOnesAndEqualThemWithinAByte) {
  const Volume volume = mixedVolume();
  checkTiles(volume, Axis::k, {});
  checkTiles(volume, Axis::i, {});
}

TEST(TileClassification, GroupsAndTilesClassifyAlikeAndNeverHideAVisibleTile) {
  const Volume volume = mixedVolume();
  const std::vector<int> spikes = {900, 1000, 1100, 1199, 1201, 2047, 3000, 4090};
  checkTiles(volume, Axis::k, spikes);
  checkTiles(volume, Axis::j, spikes);
}

TEST(TileClassification, PhantomGroupsAndTilesClassifyAlike) {
  PhantomOptions options;
  options.dims = {48, 48, 40};
  const Volume volume = generatePhantom(options).volume;
  checkTiles(volume, Axis::k, {1100, 1180, 1300, 2500});
}

// A load builds the tiles with progress and cancel: the fractions grow to 1, and an exception
// thrown from the callback leaves the build.
TEST(SliceTiles, BuildReportsGrowingProgressAndStopsOnAThrow) {
  const Volume volume = mixedVolume();
  std::vector<double> fractions;
  const SliceTiles tiles =
      buildSliceTiles(volume, Axis::k, [&](double fraction) { fractions.push_back(fraction); });
  ASSERT_FALSE(fractions.empty());
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_GT(fractions.front(), 0.0);
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  EXPECT_EQ(tiles.slices, volume.dims.z);

  struct Cancelled {};
  int calls = 0;
  EXPECT_THROW(buildSliceTiles(volume, Axis::k,
                               [&](double) {
                                 ++calls;
                                 throw Cancelled{};
                               }),
               Cancelled);
  EXPECT_GE(calls, 1);
}

}  // namespace
}  // namespace angio
