// The slice view's images: a volume whose HU is a known function of (i, j, k) gives known pixels
// at known positions in each orientation (radiological convention), through the window/level.
#include "render/slice_images.h"

#include <gtest/gtest.h>

namespace angio {
namespace {

// HU = 10 i + 100 j + 1000 k - 1000 on a 4 x 3 x 2 grid with anisotropic spacing.
Volume rampVolume() {
  Volume volume = makeVolume({4, 3, 2}, {0.5, 1.0, 2.0});
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i)
        volume.voxels[volume.indexOf(i, j, k)] = encodeVoxel(10 * i + 100 * j + 1000 * k - 1000, 3);
  return volume;
}

// A window so wide that every ramp value maps linearly: grey = (HU + 1024) / 4096 * 255.
constexpr WindowLevel kWide{4096, 1024};
std::uint8_t wideGrey(int i, int j, int k) {
  return greyOfHu(10 * i + 100 * j + 1000 * k - 1000, kWide);
}

TEST(SliceImages, WindowLevelClampsBelowAndAboveAndIsLinearBetween) {
  const WindowLevel cta{600, 250};  // -50 .. 550 HU
  EXPECT_EQ(greyOfHu(-51, cta), 0);
  EXPECT_EQ(greyOfHu(-50, cta), 0);
  EXPECT_EQ(greyOfHu(250, cta), 128);  // 127.5 rounds up
  EXPECT_EQ(greyOfHu(550, cta), 255);
  EXPECT_EQ(greyOfHu(3000, cta), 255);
  EXPECT_EQ(greyOfHu(100, cta), 64);  // 150/600 * 255 = 63.75
}

TEST(SliceImages, AxialHasPatientRightOnTheLeftAndAnteriorAtTheTop) {
  const Volume volume = rampVolume();
  const SliceImage axial = extractSlice(volume, SliceOrientation::axial, {0.5, 1.0, 2.0}, kWide);
  ASSERT_EQ(axial.width, 4);
  ASSERT_EQ(axial.height, 3);
  EXPECT_EQ(axial.index, 1);
  EXPECT_DOUBLE_EQ(axial.positionMm, 2.0);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) EXPECT_EQ(axial.at(x, y), wideGrey(x, y, 1)) << x << "," << y;
}

TEST(SliceImages, CoronalAndSagittalHaveSuperiorUp) {
  const Volume volume = rampVolume();
  const glm::dvec3 cursor{1.0, 2.0, 0.0};  // voxel (2, 2, 0)
  const SliceImage coronal = extractSlice(volume, SliceOrientation::coronal, cursor, kWide);
  ASSERT_EQ(coronal.width, 4);
  ASSERT_EQ(coronal.height, 2);
  EXPECT_EQ(coronal.index, 2);
  for (int x = 0; x < 4; ++x) {
    EXPECT_EQ(coronal.at(x, 0), wideGrey(x, 2, 1));  // top row: the superior slab k = 1
    EXPECT_EQ(coronal.at(x, 1), wideGrey(x, 2, 0));
  }
  const SliceImage sagittal = extractSlice(volume, SliceOrientation::sagittal, cursor, kWide);
  ASSERT_EQ(sagittal.width, 3);
  ASSERT_EQ(sagittal.height, 2);
  EXPECT_EQ(sagittal.index, 2);
  EXPECT_DOUBLE_EQ(sagittal.positionMm, 1.0);
  for (int x = 0; x < 3; ++x) {  // x = j: anterior (j = 0) on the left
    EXPECT_EQ(sagittal.at(x, 0), wideGrey(2, x, 1));
    EXPECT_EQ(sagittal.at(x, 1), wideGrey(2, x, 0));
  }
}

TEST(SliceImages, LabelBitsDoNotChangeTheGrey) {
  const Volume volume = rampVolume();  // every voxel carries label 3
  const SliceImage axial = extractSlice(volume, SliceOrientation::axial, {0, 0, 0}, kWide);
  EXPECT_EQ(axial.at(0, 0), greyOfHu(-1000, kWide));
}

TEST(SliceImages, ACursorOutsideTheVolumeShowsTheEdgeSlices) {
  const Volume volume = rampVolume();
  EXPECT_EQ(cursorVoxel(volume, {-5, 100, 0.9}), glm::ivec3(0, 2, 0));
  EXPECT_EQ(cursorVoxel(volume, {1.74, -1, 1.1}), glm::ivec3(3, 0, 1));
  const SliceImage axial = extractSlice(volume, SliceOrientation::axial, {0, 0, 99}, kWide);
  EXPECT_EQ(axial.index, 1);
  EXPECT_EQ(clampToVolume(volume, {-1, 5, 1}), glm::dvec3(0, 2, 1));
}

TEST(SliceImages, PixelsAndPointsMapBothWays) {
  const Volume volume = rampVolume();
  // Voxel (3, 0, 1) centre = (1.5, 0, 2) mm: sagittal pixel centre (0.5, 0.5) (anterior, superior).
  EXPECT_EQ(slicePixelOf(volume, SliceOrientation::sagittal, {1.5, 0, 2}), glm::dvec2(0.5, 0.5));
  EXPECT_EQ(slicePixelOf(volume, SliceOrientation::coronal, {1.5, 0, 0}), glm::dvec2(3.5, 1.5));
  EXPECT_EQ(slicePixelOf(volume, SliceOrientation::axial, {0.25, 1.5, 7}), glm::dvec2(1.0, 2.0));
  const glm::dvec3 cursor{0.5, 1.0, 2.0};
  for (const SliceOrientation o :
       {SliceOrientation::axial, SliceOrientation::coronal, SliceOrientation::sagittal}) {
    const glm::dvec3 point = pointOfSlicePixel(volume, o, {2.25, 1.75}, cursor);
    EXPECT_EQ(point[fixedAxisOf(o)], cursor[fixedAxisOf(o)]) << sliceOrientationName(o);
    const glm::dvec2 back = slicePixelOf(volume, o, point);
    EXPECT_NEAR(back.x, 2.25, 1e-12);
    EXPECT_NEAR(back.y, 1.75, 1e-12);
  }
}

Centerlines volumeFrame(std::vector<std::vector<glm::dvec3>> paths) {
  Centerlines centerlines;
  centerlines.frame = CenterlineFrame::volume;
  for (const auto& points : paths) {
    CenterlinePath path;
    for (const glm::dvec3& p : points) path.points.push_back({p, 1.0});
    centerlines.paths.push_back(path);
  }
  return centerlines;
}

TEST(SliceCrossings, APathThroughTheAxialPlaneCrossesItWhereItsSegmentDoes) {
  const Volume volume = makeVolume({10, 10, 10}, {1, 1, 2});
  // Axial plane at k = 2: z = 4 mm. The segment (1,2,0)-(5,6,8) is there at t = 0.5: (3, 4, 4).
  const Centerlines centerlines = volumeFrame({{{1, 2, 0}, {5, 6, 8}}, {{0, 0, 0}, {1, 1, 1}}});
  const std::vector<SliceCrossing> crossings =
      sliceCrossings(volume, SliceOrientation::axial, {0, 0, 4.3}, centerlines);
  ASSERT_EQ(crossings.size(), 1u);  // the second path stays below the plane
  EXPECT_EQ(crossings[0].path, 0);
  EXPECT_NEAR(crossings[0].pixel.x, 3.5, 1e-12);
  EXPECT_NEAR(crossings[0].pixel.y, 4.5, 1e-12);
}

TEST(SliceCrossings, APolylineTouchingThePlaneAtAVertexCrossesOnceAndABackAndForthTwice) {
  const Volume volume = makeVolume({10, 10, 10}, {1, 1, 1});
  const Centerlines through = volumeFrame({{{2, 0, 5}, {2, 3, 5}, {2, 6, 5}}});  // j goes 0 -> 6
  const auto once = sliceCrossings(volume, SliceOrientation::coronal, {0, 3, 0}, through);
  ASSERT_EQ(once.size(), 1u);
  EXPECT_NEAR(once[0].pixel.x, 2.5, 1e-12);
  EXPECT_NEAR(once[0].pixel.y, 10 - 1 - 5 + 0.5, 1e-12);                      // superior up
  const Centerlines loop = volumeFrame({{{4, 1, 1}, {6, 1, 1}, {2, 1, 1}}});  // i: 4 -> 6 -> 2
  EXPECT_EQ(sliceCrossings(volume, SliceOrientation::sagittal, {5, 0, 0}, loop).size(), 2u);
}

TEST(SliceCrossings, PhysicalFrameCenterlinesAreRejected) {
  const Volume volume = makeVolume({2, 2, 2}, {1, 1, 1});
  Centerlines physical;
  EXPECT_THROW(sliceCrossings(volume, SliceOrientation::axial, {0, 0, 0}, physical), std::logic_error);
}

}  // namespace
}  // namespace angio
