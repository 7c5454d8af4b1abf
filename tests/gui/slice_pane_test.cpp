// The slice view's geometry and gestures: an anisotropic slice keeps its mm proportions and maps
// screen to pixel and back, letters follow the radiological convention of render/slice_images.h,
// the wheel steps voxel centres inside the volume, a right-drag sets window/level.
#include "gui/slice_pane.h"

#include <gtest/gtest.h>

namespace angio {
namespace {

TEST(SlicePane, AnAnisotropicSliceFitsItsPaneWithSquareMillimetres) {
  // 100 x 40 pixels of 0.5 x 2.5 mm: 50 x 100 mm, in a 300 x 300 pane: 3 screen px per mm, the
  // height fills it, the width is centred.
  const SlicePlacement p = placeSlice({100, 40}, {0.5, 2.5}, {10, 20}, {300, 300});
  EXPECT_DOUBLE_EQ(p.scale.x, 1.5);
  EXPECT_DOUBLE_EQ(p.scale.y, 7.5);
  EXPECT_DOUBLE_EQ(p.size.x, 150);
  EXPECT_DOUBLE_EQ(p.size.y, 300);
  EXPECT_DOUBLE_EQ(p.min.x, 10 + 75);
  EXPECT_DOUBLE_EQ(p.min.y, 20);
  const glm::dvec2 pixel(37.25, 11.5);
  const glm::dvec2 back = slicePixelOfScreen(p, screenOfSlicePixel(p, pixel));
  EXPECT_NEAR(back.x, pixel.x, 1e-12);
  EXPECT_NEAR(back.y, pixel.y, 1e-12);
  EXPECT_DOUBLE_EQ(screenOfSlicePixel(p, {100, 40}).x, 10 + 75 + 150);  // the far corner
}

TEST(SlicePane, AZoomedSliceScalesAboutThePanesCentreAndMovesByThePan) {
  // The slice of the test above at zoom 2, panned (20, -10): 6 screen px per mm, its centre at
  // the pane's centre (160, 170) plus the pan.
  const SlicePlacement p = placeSlice({100, 40}, {0.5, 2.5}, {10, 20}, {300, 300}, 2, {20, -10});
  EXPECT_DOUBLE_EQ(p.scale.x, 3);
  EXPECT_DOUBLE_EQ(p.scale.y, 15);
  EXPECT_DOUBLE_EQ(p.size.y, 600);
  EXPECT_DOUBLE_EQ(p.min.x + p.size.x / 2, 160 + 20);
  EXPECT_DOUBLE_EQ(p.min.y + p.size.y / 2, 170 - 10);
}

TEST(SlicePane, LettersAreRadiological) {
  EXPECT_EQ(sliceLetters(SliceOrientation::axial), (SliceLetters{'R', 'L', 'A', 'P'}));
  EXPECT_EQ(sliceLetters(SliceOrientation::coronal), (SliceLetters{'R', 'L', 'S', 'I'}));
  EXPECT_EQ(sliceLetters(SliceOrientation::sagittal), (SliceLetters{'A', 'P', 'S', 'I'}));
  // They agree with the images: in the axial image a point further left (+i, the patient's left)
  // lies further right, a point further anterior (-j) higher up.
  const Volume volume = makeVolume({10, 12, 14}, {1, 1, 2});
  const glm::dvec3 p(4, 5, 6);
  EXPECT_GT(slicePixelOf(volume, SliceOrientation::axial, p + glm::dvec3(1, 0, 0)).x,
            slicePixelOf(volume, SliceOrientation::axial, p).x);
  EXPECT_LT(slicePixelOf(volume, SliceOrientation::axial, p - glm::dvec3(0, 1, 0)).y,
            slicePixelOf(volume, SliceOrientation::axial, p).y);
  // Coronal and sagittal: superior (+k) is up.
  EXPECT_LT(slicePixelOf(volume, SliceOrientation::sagittal, p + glm::dvec3(0, 0, 2)).y,
            slicePixelOf(volume, SliceOrientation::sagittal, p).y);
}

TEST(SlicePane, TheWheelStepsVoxelCentresAndStopsAtTheEdges) {
  const Volume volume = makeVolume({10, 12, 14}, {0.5, 0.75, 2});
  const glm::dvec3 cursor(1.2, 3.1, 7.3);  // nearest voxel k = 4 (8 mm)
  const glm::dvec3 up = steppedCursor(volume, SliceOrientation::axial, cursor, 1);
  EXPECT_DOUBLE_EQ(up.z, 10);
  EXPECT_DOUBLE_EQ(up.x, cursor.x);  // in-plane coordinates stay
  EXPECT_DOUBLE_EQ(up.y, cursor.y);
  EXPECT_DOUBLE_EQ(steppedCursor(volume, SliceOrientation::axial, cursor, -10).z, 0);
  EXPECT_DOUBLE_EQ(steppedCursor(volume, SliceOrientation::axial, cursor, 100).z, 26);
  EXPECT_DOUBLE_EQ(steppedCursor(volume, SliceOrientation::sagittal, cursor, 3).x, 2.5);   // i 2 -> 5
  EXPECT_DOUBLE_EQ(steppedCursor(volume, SliceOrientation::coronal, cursor, -1).y, 2.25);  // j 4 -> 3
}

TEST(SlicePane, ARightDragSetsWindowAndLevelAndTheWindowStaysPositive) {
  const WindowLevel start{600, 250};
  EXPECT_EQ(draggedWindowLevel(start, {0, 0}), start);
  EXPECT_EQ(draggedWindowLevel(start, {10, -5}),
            (WindowLevel{600 + 10 * kWindowLevelHuPerPixel, 250 - 5 * kWindowLevelHuPerPixel}));
  EXPECT_EQ(draggedWindowLevel(start, {-1000, 0}).window, 1);
}

}  // namespace
}  // namespace angio
