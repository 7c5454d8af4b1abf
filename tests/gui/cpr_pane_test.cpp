// The CPR pane's placement at zoom and pan, the zoom about the pointer, and the ruler's spacing.
#include "gui/cpr_pane.h"

#include <gtest/gtest.h>

#include "gui/zoom_pan.h"

namespace angio {
namespace {

TEST(CprPane, AtZoomOneTheImageFitsTheTopOfThePaneCentredAcross) {
  // 100 x 400 pixels in a 300 x 800 pane at (10, 20): the height limits, 2 screen px per pixel.
  const CprPlacement placement = placeCpr({100, 400}, {10, 20}, {300, 800}, 1, {0, 0});
  EXPECT_DOUBLE_EQ(placement.scale, 2);
  EXPECT_EQ(placement.min, glm::dvec2(10 + 150 - 100, 20));
  EXPECT_EQ(screenOfCprPixel(placement, {0, 0}), placement.min + 1.0);  // a pixel's centre
  EXPECT_EQ(cprPixelUnder(placement, placement.min + glm::dvec2(3.9, 1.9)), glm::ivec2(1, 0));
  EXPECT_EQ(cprPixelUnder(placement, placement.min - 0.1), glm::ivec2(-1, -1));  // outside
  // A wide image is limited by the pane's width and sits at its top.
  const CprPlacement wide = placeCpr({600, 100}, {0, 0}, {300, 800}, 1, {0, 0});
  EXPECT_DOUBLE_EQ(wide.scale, 0.5);
  EXPECT_EQ(wide.min, glm::dvec2(0, 0));
}

TEST(CprPane, ZoomAndPanScaleAboutTheHomeCentreAndTheWheelKeepsThePixelUnderThePointer) {
  const glm::ivec2 image{100, 400};
  const glm::dvec2 paneMin{10, 20}, pane{300, 800};
  const CprPlacement one = placeCpr(image, paneMin, pane, 1, {0, 0});
  const CprPlacement two = placeCpr(image, paneMin, pane, 2, {5, -7});
  EXPECT_DOUBLE_EQ(two.scale, 2 * one.scale);
  EXPECT_EQ(screenOfCprPixel(two, {49.5, 199.5}), one.home + glm::dvec2(5, -7));  // image centre

  double zoom = 1.5;
  glm::dvec2 pan{12, 30};
  const glm::dvec2 pointer{70, 300};
  const CprPlacement before = placeCpr(image, paneMin, pane, zoom, pan);
  const glm::dvec2 pixelBefore = (pointer - before.min) / before.scale;
  zoomAboutPointer(zoom, pan, pointer - before.home, 2, kMinCprZoom, kMaxCprZoom);
  EXPECT_DOUBLE_EQ(zoom, 1.5 * 1.44);
  const CprPlacement after = placeCpr(image, paneMin, pane, zoom, pan);
  const glm::dvec2 pixelAfter = (pointer - after.min) / after.scale;
  EXPECT_NEAR(pixelAfter.x, pixelBefore.x, 1e-9);
  EXPECT_NEAR(pixelAfter.y, pixelBefore.y, 1e-9);
}

TEST(CprPane, RulerTicksStayApartOnTheScreen) {
  EXPECT_EQ(rulerStepMm(10), 1);    // 10 px per mm: every mm
  EXPECT_EQ(rulerStepMm(2), 5);     // 2 px/mm: 2 mm would be 4 px, 5 mm is 10
  EXPECT_EQ(rulerStepMm(0.6), 10);  // a fitted aorta CPR
  EXPECT_EQ(rulerStepMm(0.01), 100);
}

}  // namespace
}  // namespace angio
