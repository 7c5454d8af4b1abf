// After a label change the renderer refreshes only the slices of its tiles that the change
// touched (core/slice_tiles.h refreshSliceTiles), or takes tiles built ahead with the change's
// labels as an overlay. Checked against the tiles built from scratch
// on the changed volume, array by array, for every rotation axis, for changes that add the first
// label, add more, and take the last away.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <numeric>

#include "core/slice_tiles.h"
#include "phantom/phantom.h"

namespace angio {
namespace {

void expectSameRanges(const PackedRanges& a, const PackedRanges& b, const char* what) {
  EXPECT_EQ(a.minOffset, b.minOffset) << what;
  EXPECT_EQ(a.maxOffset, b.maxOffset) << what;
  ASSERT_EQ(a.scale.size(), b.scale.size()) << what;
  for (std::size_t g = 0; g < a.scale.size(); ++g) {
    EXPECT_EQ(a.scale[g].base, b.scale[g].base) << what << " group " << g;
    EXPECT_EQ(a.scale[g].shift, b.scale[g].shift) << what << " group " << g;
    EXPECT_EQ(a.scale[g].top, b.scale[g].top) << what << " group " << g;
  }
}

void expectSameTiles(const SliceTiles& a, const SliceTiles& b) {
  ASSERT_EQ(a.axis, b.axis);
  ASSERT_EQ(a.labelled, b.labelled);
  for (const Filter filter : {Filter::trilinear, Filter::mean}) {
    const TileRanges &ra = a.reach(filter), &rb = b.reach(filter);
    expectSameRanges(ra.unlabelled, rb.unlabelled, "unlabelled");
    expectSameRanges(ra.labelled, rb.labelled, "labelled");
    EXPECT_EQ(ra.labelBits, rb.labelBits);
  }
}

Volume smallPhantom() {
  PhantomOptions options;
  options.dims = {37, 29, 24};  // ragged tiles and groups along every axis
  return generatePhantom(options).volume;
}

// The voxels of the box [lo, hi] (inclusive), ascending, as a LabelChange lists them.
std::vector<std::size_t> boxVoxels(const Volume& volume, glm::ivec3 lo, glm::ivec3 hi) {
  std::vector<std::size_t> voxels;
  for (int k = lo.z; k <= hi.z; ++k)
    for (int j = lo.y; j <= hi.y; ++j)
      for (int i = lo.x; i <= hi.x; ++i) voxels.push_back(volume.indexOf(i, j, k));
  return voxels;
}

void setLabel(Volume& volume, const std::vector<std::size_t>& voxels, int label) {
  for (const std::size_t n : voxels)
    volume.voxels[n] = Voxel(densityOf(volume.voxels[n]) | (label << 12));
}

// Labels `voxels` in `volume`, refreshes `tiles` for the slices holding them and checks them
// against a build from scratch.
void changeAndCheck(Volume& volume, SliceTiles& tiles, const std::vector<std::size_t>& voxels,
                    int label) {
  setLabel(volume, voxels, label);
  refreshSliceTiles(tiles, volume, slicesHolding(volume, tiles.axis, voxels));
  expectSameTiles(tiles, buildSliceTiles(volume, tiles.axis));
}

TEST(SliceTilesRefresh, EqualsABuildFromScratchAfterEachLabelChange) {
  for (const Axis axis : {Axis::i, Axis::j, Axis::k}) {
    SCOPED_TRACE(toString(axis));
    Volume volume = smallPhantom();
    SliceTiles tiles = buildSliceTiles(volume, axis);
    ASSERT_FALSE(tiles.labelled);
    const std::vector<std::size_t> first = boxVoxels(volume, {3, 4, 5}, {9, 8, 7});
    const std::vector<std::size_t> second = boxVoxels(volume, {20, 10, 12}, {30, 25, 20});
    changeAndCheck(volume, tiles, first, 1);  // the first label: the label parts appear
    EXPECT_TRUE(tiles.labelled);
    changeAndCheck(volume, tiles, second, 3);
    changeAndCheck(volume, tiles, second, 0);  // one taken back: labels stay
    EXPECT_TRUE(tiles.labelled);
    changeAndCheck(volume, tiles, first, 0);  // the last one: the label parts go
    EXPECT_FALSE(tiles.labelled);
  }
}

// The check above can fail: leaving out one slice the change touched leaves its tiles stale.
TEST(SliceTilesRefresh, ASliceLeftOutStaysAsItWas) {
  Volume volume = smallPhantom();
  const std::vector<std::size_t> box = boxVoxels(volume, {3, 4, 5}, {9, 8, 7});
  setLabel(volume, box, 2);
  SliceTiles tiles = buildSliceTiles(volume, Axis::k);
  setLabel(volume, box, 4);
  std::vector<int> slices = slicesHolding(volume, Axis::k, box);
  ASSERT_EQ(slices, (std::vector<int>{5, 6, 7}));
  slices.pop_back();
  refreshSliceTiles(tiles, volume, slices);
  const SliceTiles built = buildSliceTiles(volume, Axis::k);
  const std::size_t firstOfSlice7 = std::size_t(7) * tiles.tilesPerSlice();
  EXPECT_TRUE(std::equal(tiles.cells.labelBits.begin(), tiles.cells.labelBits.begin() + firstOfSlice7,
                         built.cells.labelBits.begin()));
  EXPECT_FALSE(std::equal(tiles.cells.labelBits.begin() + firstOfSlice7, tiles.cells.labelBits.end(),
                          built.cells.labelBits.begin() + firstOfSlice7));
}

// Built ahead from the volume as it is and the change's labels (the volume left alone), the tiles
// equal a build from scratch on the changed volume: the first labels, more, the last taken away.
TEST(SliceTilesAhead, AnOverlayBuildEqualsABuildOfTheChangedVolume) {
  for (const Axis axis : {Axis::j, Axis::k}) {
    SCOPED_TRACE(toString(axis));
    Volume volume = smallPhantom();
    const std::vector<std::size_t> first = boxVoxels(volume, {3, 4, 5}, {9, 8, 7});
    std::vector<std::size_t> second = boxVoxels(volume, {20, 10, 12}, {30, 25, 20});
    std::vector<std::uint8_t> labels(second.size());
    for (std::size_t n = 0; n < labels.size(); ++n) labels[n] = std::uint8_t(1 + n % 5);
    for (const auto& [voxels, labelled] :
         {std::pair{first, std::vector<std::uint8_t>(first.size(), 2)}, std::pair{second, labels},
          std::pair{second, std::vector<std::uint8_t>(second.size(), 0)},
          std::pair{first, std::vector<std::uint8_t>(first.size(), 0)}}) {
      const std::vector<Voxel> before = volume.voxels;
      const SliceTiles ahead = buildSliceTiles(volume, axis, LabelOverlay{voxels, labelled});
      EXPECT_EQ(volume.voxels, before);
      for (std::size_t n = 0; n < voxels.size(); ++n)
        volume.voxels[voxels[n]] = withLabel(volume.voxels[voxels[n]], labelled[n]);
      expectSameTiles(ahead, buildSliceTiles(volume, axis));
    }
    EXPECT_FALSE(buildSliceTiles(volume, axis).labelled);  // the last step took every label away
  }
  const std::vector<std::size_t> none;
  const std::vector<std::uint8_t> noLabels;
  EXPECT_THROW(buildSliceTiles(smallPhantom(), Axis::i, LabelOverlay{none, noLabels}),
               std::invalid_argument);
}

// A renderer builds new tiles in groups of slices between its cancellation checks, in any order.
TEST(SliceTilesInParts, SummarisedGroupByGroupTheyEqualABuildInOne) {
  for (const bool labelled : {false, true}) {
    Volume volume = smallPhantom();
    if (labelled) setLabel(volume, boxVoxels(volume, {3, 4, 5}, {9, 8, 7}), 2);
    ASSERT_EQ(volumeHasLabels(volume), labelled);
    for (const Axis axis : {Axis::i, Axis::j, Axis::k}) {
      SCOPED_TRACE(std::string(toString(axis)) + (labelled ? " labelled" : ""));
      SliceTiles tiles = unsummarisedSliceTiles(volume, axis, labelled);
      std::vector<int> odd, even;
      for (int slice = 0; slice < tiles.slices; ++slice) (slice % 2 ? odd : even).push_back(slice);
      summariseSliceTiles(tiles, volume, odd);
      std::reverse(even.begin(), even.end());
      for (const int slice : even) summariseSliceTiles(tiles, volume, {slice});
      const SliceTiles built = buildSliceTiles(volume, axis);
      expectSameTiles(tiles, built);

      SliceTiles grouped = unsummarisedSliceTiles(volume, axis, labelled);
      std::vector<int> unbuilt(std::size_t(grouped.slices));
      std::iota(unbuilt.begin(), unbuilt.end(), 0);
      std::atomic<bool> cancel{true};
      EXPECT_FALSE(summariseSliceTiles(grouped, volume, unbuilt, &cancel));
      EXPECT_EQ(unbuilt.size(), std::size_t(grouped.slices));
      cancel = false;
      std::vector<double> fractions;  // reported, one per group
      EXPECT_TRUE(summariseSliceTiles(grouped, volume, unbuilt, &cancel,
                                      [&](double fraction) { fractions.push_back(fraction); }));
      EXPECT_TRUE(unbuilt.empty());
      ASSERT_FALSE(fractions.empty());
      EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
      EXPECT_GT(fractions.front(), 0.0);
      EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
      expectSameTiles(grouped, built);
    }
  }
}

TEST(SliceTilesRefresh, SlicesHoldingAreThoseOfTheVoxelsAlongEachAxis) {
  const Volume volume = smallPhantom();
  std::vector<std::size_t> voxels = boxVoxels(volume, {3, 4, 5}, {4, 5, 6});
  const std::vector<std::size_t> more = boxVoxels(volume, {30, 20, 20}, {30, 20, 20});
  voxels.insert(voxels.end(), more.begin(), more.end());
  EXPECT_EQ(slicesHolding(volume, Axis::i, voxels), (std::vector<int>{3, 4, 30}));
  EXPECT_EQ(slicesHolding(volume, Axis::j, voxels), (std::vector<int>{4, 5, 20}));
  EXPECT_EQ(slicesHolding(volume, Axis::k, voxels), (std::vector<int>{5, 6, 20}));
  EXPECT_TRUE(slicesHolding(volume, Axis::k, {}).empty());
}

}  // namespace
}  // namespace angio
