// Label changes: the difference to new labels, undo and redo of exactly those voxels, counts.
#include "gui/label_change.h"

#include <gtest/gtest.h>

namespace angio {
namespace {

TEST(LabelChange, ChangeToUndoAndRedoRestoreTheLabelsAndTheCounts) {
  Volume volume = makeVolume({4, 4, 4}, {1, 1, 1}, encodeVoxel(100));
  volume.voxels[5] = encodeVoxel(100, 3);
  const Volume original = volume;
  LabelCounts counts = countLabels(volume);
  EXPECT_EQ(counts[0], 63u);
  EXPECT_EQ(counts[3], 1u);
  std::vector<std::uint8_t> labels(64, 0);
  labels[5] = 3;              // unchanged
  labels[0] = labels[1] = 1;  // new bone
  labels[63] = 2;             // new table
  const LabelChange change = changeTo(volume, labels, "removal");
  EXPECT_EQ(change.voxels, (std::vector<std::size_t>{0, 1, 63}));
  apply(change, false, volume, counts);
  EXPECT_EQ(labelOf(volume.voxels[1]), 1);
  EXPECT_EQ(densityOf(volume.voxels[1]), densityOfHu(100));  // densities untouched
  EXPECT_EQ(counts, countLabels(volume));
  apply(change, true, volume, counts);
  EXPECT_EQ(volume.voxels, original.voxels);
  EXPECT_EQ(counts, countLabels(original));
}

TEST(LabelChange, ChangeOfLeavesOutVoxelsThatHaveTheLabelAlready) {
  Volume volume = makeVolume({4, 1, 1}, {1, 1, 1}, encodeVoxel(0));
  volume.voxels[2] = encodeVoxel(0, 1);
  const LabelChange change = changeOf(volume, {0, 2, 3}, 1, "grow");
  EXPECT_EQ(change.voxels, (std::vector<std::size_t>{0, 3}));
  EXPECT_EQ(change.before, (std::vector<std::uint8_t>{0, 0}));
}

}  // namespace
}  // namespace angio
