// Interactive labelling: the connected structure in an HU range from a seed, holes filled, other
// labels never taken; the connected piece of one label for "give back".
#include "segment/region_growing.h"

#include <atomic>

#include <gtest/gtest.h>

namespace angio {
namespace {

// 40^3 voxels of soft tissue (40 HU) with a hollow "bone": a 1000 HU shell of a 12^3 box around
// 200 HU marrow, and a 350 HU "vessel" rod touching the shell.
Volume boneAndVessel() {
  Volume volume = makeVolume({40, 40, 40}, {1, 1, 1}, encodeVoxel(40));
  for (int k = 10; k < 22; ++k)
    for (int j = 10; j < 22; ++j)
      for (int i = 10; i < 22; ++i) {
        const bool shell = i == 10 || i == 21 || j == 10 || j == 21 || k == 10 || k == 21;
        volume.voxels[volume.indexOf(i, j, k)] = encodeVoxel(shell ? 1000 : 200);
      }
  for (int k = 0; k < 40; ++k) volume.voxels[volume.indexOf(22, 15, k)] = encodeVoxel(350);
  return volume;
}

TEST(RegionGrowing, GrowsTheCortexAndFillsTheMarrowButNotTheVessel) {
  const Volume volume = boneAndVessel();
  const GrowSettings settings{500, 3071, 1, true};
  const std::vector<std::size_t> grown = growRegion(volume, {10, 15, 15}, settings);
  EXPECT_EQ(grown.size(), std::size_t(12 * 12 * 12));  // shell and marrow, no vessel voxel
  EXPECT_TRUE(std::is_sorted(grown.begin(), grown.end()));
  for (const std::size_t n : grown) EXPECT_NE(volume.voxels[n], encodeVoxel(350));
  GrowSettings noFill = settings;
  noFill.fillHoles = false;
  EXPECT_EQ(growRegion(volume, {10, 15, 15}, noFill).size(), std::size_t(12 * 12 * 12 - 10 * 10 * 10));
}

TEST(RegionGrowing, AWideRangeLeaksIntoTheVesselAsAClinicianWouldExpect) {
  const Volume volume = boneAndVessel();
  const std::vector<std::size_t> grown = growRegion(volume, {10, 15, 15}, {300, 3071, 1, false});
  EXPECT_EQ(grown.size(), std::size_t(12 * 12 * 12 - 10 * 10 * 10 + 40));  // shell + the whole rod
}

TEST(RegionGrowing, OtherLabelsStopTheRegionAndASeedOutsideTheRangeGrowsNothing) {
  Volume volume = boneAndVessel();
  // Label the shell's face at i = 10 as a user label: the seed there cannot grow into label 1.
  for (int k = 10; k < 22; ++k)
    for (int j = 10; j < 22; ++j) volume.voxels[volume.indexOf(10, j, k)] = encodeVoxel(1000, 3);
  EXPECT_TRUE(growRegion(volume, {10, 15, 15}, {500, 3071, 1, false}).empty());
  const std::vector<std::size_t> rest = growRegion(volume, {21, 15, 15}, {500, 3071, 1, false});
  EXPECT_EQ(rest.size(), std::size_t(12 * 12 * 12 - 10 * 10 * 10 - 12 * 12));
  EXPECT_TRUE(growRegion(volume, {0, 0, 0}, {500, 3071, 1, false}).empty());  // 40 HU seed
  EXPECT_TRUE(growRegion(volume, {-1, 0, 0}, {500, 3071, 1, false}).empty());
}

TEST(RegionGrowing, ConnectedLabelledTakesTheSeedsPieceOnly) {
  Volume volume = makeVolume({20, 20, 20}, {1, 1, 1});
  for (int i = 2; i < 6; ++i) volume.voxels[volume.indexOf(i, 5, 5)] = encodeVoxel(0, 2);
  for (int i = 10; i < 13; ++i) volume.voxels[volume.indexOf(i, 5, 5)] = encodeVoxel(0, 2);
  EXPECT_EQ(connectedLabelled(volume, {3, 5, 5}).size(), 4u);
  EXPECT_EQ(connectedLabelled(volume, {11, 5, 5}).size(), 3u);
  EXPECT_TRUE(connectedLabelled(volume, {0, 0, 0}).empty());
}

TEST(RegionGrowing, ACancelledGrowReturnsNothing) {
  const Volume volume = boneAndVessel();
  const std::atomic<bool> cancel{true};
  EXPECT_TRUE(growRegion(volume, {10, 15, 15}, {500, 3071, 1, true}, &cancel).empty());
}

}  // namespace
}  // namespace angio
