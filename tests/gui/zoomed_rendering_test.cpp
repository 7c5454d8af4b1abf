// What a zoomed view renders: the visible part of the image plane and each level's isd, against
// the viewport geometry worked out by hand.
#include <gtest/gtest.h>

#include "gui/zoomed_rendering.h"

namespace angio {
namespace {

// A 400 x 200 px viewport fitting 100 x 50 mm: 4 px/mm at zoom 1 times the 0.95 fit margin.
const ViewportFit kFit{{400, 200}, {100, 50}};

TEST(ZoomedRendering, UpToZoomOneTheWholeImageAtTheLevelsSampling) {
  ViewState view;
  view.zoom = 1;
  view.panPx = {50, -20};
  EXPECT_FALSE(visibleWindow(view, kFit));
  const LevelSamplings levels = defaultLevelSamplings();
  EXPECT_EQ(zoomedLevels(levels, 1, 0.01), levels);
  EXPECT_EQ(zoomedLevels(levels, 0.5, 0.01), levels);
}

TEST(ZoomedRendering, TheWindowIsWhatTheViewportShowsOnA32PixelGrid) {
  ViewState view;
  view.zoom = 4;
  const double perMm = 4 * 0.95 * 4;  // 15.2 px/mm
  EXPECT_DOUBLE_EQ(viewportPixelsPerMm(kFit, view.zoom), perMm);
  const double step = 32 / perMm;
  const auto centred = visibleWindow(view, kFit);
  ASSERT_TRUE(centred);
  // 200 px each side of the centre: 6.25 grid steps, widened to 7.
  EXPECT_DOUBLE_EQ(centred->rightMm, 7 * step);
  EXPECT_DOUBLE_EQ(centred->leftMm, -7 * step);
  EXPECT_DOUBLE_EQ(centred->topMm, 4 * step);  // 100 px: 3.125 steps
  EXPECT_DOUBLE_EQ(centred->bottomMm, -4 * step);
  // Panning the image 64 px right and 32 px down shows what lies 2 steps left and 1 step up.
  view.panPx = {64, 32};
  const auto panned = visibleWindow(view, kFit);
  ASSERT_TRUE(panned);
  EXPECT_DOUBLE_EQ(panned->leftMm, -9 * step);
  EXPECT_DOUBLE_EQ(panned->rightMm, 5 * step);
  EXPECT_DOUBLE_EQ(panned->topMm, 5 * step);
  EXPECT_DOUBLE_EQ(panned->bottomMm, -3 * step);
  // A pan of a few pixels keeps the window, so the frame shown stays the one asked for.
  view.panPx = {66, 35};
  EXPECT_EQ(visibleWindow(view, kFit), panned);
}

TEST(ZoomedRendering, EachLevelGetsFinerByTheZoomDownToAScreenPixel) {
  const LevelSamplings levels = defaultLevelSamplings();  // isd 3, 1, 0.5
  const LevelSamplings zoomed = zoomedLevels(levels, 4, 0.2);
  EXPECT_DOUBLE_EQ(zoomed[0].isd, 0.75);
  EXPECT_DOUBLE_EQ(zoomed[1].isd, 0.25);
  EXPECT_DOUBLE_EQ(zoomed[2].isd, 0.2);  // 0.125 would be finer than the screen
  EXPECT_EQ(zoomed[2].osd, levels[2].osd);
  // A screen coarser than a level at this zoom: the level never gets coarser than its own isd.
  EXPECT_DOUBLE_EQ(zoomedLevels(levels, 1.5, 0.9)[2].isd, 0.5);
}

}  // namespace
}  // namespace angio
