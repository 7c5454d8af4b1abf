// Whether densities look like calibrated HU (core/volume.h): a body CT holds air below -500 HU in
// at least 0.1 % of its voxels; the histogram and the volume give the same answer.
#include <gtest/gtest.h>

#include "core/volume.h"

namespace angio {
namespace {

TEST(HuCalibration, AirInOnePerMilleOfTheVoxelsLooksCalibrated) {
  Volume volume = makeVolume({10, 10, 20}, {1, 1, 1}, encodeVoxel(40));  // 2000 voxels of soft tissue
  EXPECT_FALSE(looksHuCalibrated(volume));
  volume.voxels[0] = encodeVoxel(-1000);  // 1 of 2000: below the threshold
  EXPECT_FALSE(looksHuCalibrated(volume));
  volume.voxels[1] = encodeVoxel(-600);  // 2 of 2000 = 0.1 %
  EXPECT_TRUE(looksHuCalibrated(volume));
  EXPECT_TRUE(looksHuCalibrated(densityHistogram(volume)));
  volume.voxels[1] = encodeVoxel(-500);  // -500 itself is not air
  EXPECT_FALSE(looksHuCalibrated(densityHistogram(volume)));
}

}  // namespace
}  // namespace angio
