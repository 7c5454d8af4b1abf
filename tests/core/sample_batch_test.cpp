// The sample batches' voxel addressing (core/sample_batch.h), checked by arithmetic: the lanes hold
// offsets from an even origin, and origin + offset is the voxel index, also for volumes of 2^31
// voxels or more, whose indices a 32-bit lane cannot hold.
#include "core/sample_batch.h"

#include <array>
#include <cstdint>

#include <gtest/gtest.h>

namespace angio {
namespace {

// Two halves of lanes holding index(j) for lane j.
template <class Index>
std::array<DoubleLanes, 2> indexLanes(Index index) {
  alignas(64) std::array<double, kBatchSamples> lanes;
  for (int j = 0; j < kBatchSamples; ++j) lanes[j] = double(index(j));
  return {DoubleLanes::load_aligned(lanes.data()),
          DoubleLanes::load_aligned(lanes.data() + DoubleLanes::size)};
}

std::array<std::int32_t, kBatchSamples> offsets(const VoxelLanes& lanes) {
  alignas(64) std::array<std::int32_t, kBatchSamples> values;
  lanes.offset.store_aligned(values.data());
  return values;
}

TEST(SampleBatch, VoxelLanesAddBackToIndicesPast32Bits) {
  // A ray through a 1024 x 1024 x 2400 volume near its far end, going down in i and up in k.
  const std::int64_t slice = 1024 * 1024, start = std::int64_t(2398) * slice + 5 * 1024 + 1001;
  for (const std::int64_t first : {start, start + 1}) {  // odd and even first index
    const auto index = [&](int j) { return first - 3 * j + j * slice; };
    VoxelLanes lanes;
    ASSERT_TRUE(voxelLanes(indexLanes(index), 1 + 1024 + slice, lanes));
    EXPECT_EQ(lanes.origin % 2, 0u);
    const auto offset = offsets(lanes);
    for (int j = 0; j < kBatchSamples; ++j)
      EXPECT_EQ(std::int64_t(lanes.origin) + offset[j], index(j)) << "lane " << j;
  }
}

TEST(SampleBatch, VoxelLanesRefuseLanesTooFarApart) {
  VoxelLanes lanes;
  // 2^31 voxels between the first lane and the last: no 32-bit offset reaches both.
  EXPECT_FALSE(voxelLanes(indexLanes([](int j) { return std::int64_t(j) << 28; }), 0, lanes));
  // Near the limit, the caller's reach decides.
  const auto nearLimit = [](int j) { return j == 7 ? (std::int64_t{1} << 30) - 100 : j; };
  EXPECT_TRUE(voxelLanes(indexLanes(nearLimit), 50, lanes));
  EXPECT_FALSE(voxelLanes(indexLanes(nearLimit), 200, lanes));
}

}  // namespace
}  // namespace angio
