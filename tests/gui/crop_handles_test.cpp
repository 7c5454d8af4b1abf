// The crop box's handles: one per face whose axis shows on screen, at the face's centre, and a
// drag that moves the face by the pointer's motion along the face's screen direction.
#include "gui/crop_handles.h"

#include <gtest/gtest.h>

namespace angio {
namespace {

// A view along +j: i to the right at 2 px/mm, k up at 2 px/mm, j (depth) not on screen.
glm::dvec2 alongJ(glm::dvec3 mm) { return {100 + 2 * mm.x, 500 - 2 * mm.z}; }

const CropBox kBox{{10, 20, 30}, {50, 60, 130}};
const glm::dvec3 kExtent{100, 100, 200};

TEST(CropHandles, EachFaceWhoseAxisShowsHasAHandleAtItsCentre) {
  const std::vector<CropHandle> handles = cropHandles(kBox, alongJ);
  ASSERT_EQ(handles.size(), 4u);  // the two j faces face the viewer
  for (const CropHandle& handle : handles) EXPECT_NE(handle.face.axis, 1);
  const std::optional<CropHandle> top = handleAt(handles, alongJ({30, 40, 130}), 1);
  ASSERT_TRUE(top);
  EXPECT_EQ(top->face, (CropFace{2, true}));
  EXPECT_EQ(top->screenPerMm, glm::dvec2(0, -2));
  EXPECT_FALSE(handleAt(handles, alongJ({30, 40, 80}), 8));  // the box's centre: no face there
}

TEST(CropHandles, TheNearestHandleWithinTheRadiusIsGrabbed) {
  const std::vector<CropHandle> handles = cropHandles(kBox, alongJ);
  const glm::dvec2 left = alongJ({10, 40, 80});
  EXPECT_EQ(handleAt(handles, left + glm::dvec2(5, 3), 8)->face, (CropFace{0, false}));
  EXPECT_FALSE(handleAt(handles, left + glm::dvec2(9, 0), 8));
}

TEST(CropHandles, ADragMovesTheFaceByThePointersMotionAlongItsAxis) {
  const CropHandle top = *handleAt(cropHandles(kBox, alongJ), alongJ({30, 40, 130}), 1);
  // 20 px up is 10 mm along +k; sideways motion does not count.
  CropBox moved = draggedCropBox(kBox, top, {7, -20}, kExtent);
  EXPECT_DOUBLE_EQ(moved.maxMm.z, 140);
  EXPECT_EQ(moved.minMm, kBox.minMm);
  EXPECT_EQ(glm::dvec2(moved.maxMm.x, moved.maxMm.y), glm::dvec2(kBox.maxMm.x, kBox.maxMm.y));
  // Not beyond the volume, not past the opposite face.
  EXPECT_DOUBLE_EQ(draggedCropBox(kBox, top, {0, -1000}, kExtent).maxMm.z, 200);
  EXPECT_DOUBLE_EQ(draggedCropBox(kBox, top, {0, 1000}, kExtent).maxMm.z, 30);
  const CropHandle left = *handleAt(cropHandles(kBox, alongJ), alongJ({10, 40, 80}), 1);
  EXPECT_DOUBLE_EQ(draggedCropBox(kBox, left, {-1000, 0}, kExtent).minMm.x, 0);
  EXPECT_DOUBLE_EQ(draggedCropBox(kBox, left, {1000, 0}, kExtent).minMm.x, 50);
}

TEST(CropHandles, AnObliqueAxisMovesByThePointersProjectionOntoIt) {
  // i and j both on screen at 45 degrees: the i axis runs (1, 1)/sqrt 2 at 2 px/mm.
  const auto oblique = [](glm::dvec3 mm) {
    return glm::dvec2(std::sqrt(2.0) * (mm.x + mm.y), std::sqrt(2.0) * (mm.x - mm.y) - 2 * mm.z);
  };
  const std::vector<CropHandle> handles = cropHandles(kBox, oblique);
  EXPECT_EQ(handles.size(), 6u);
  const CropHandle right = *handleAt(handles, oblique({50, 40, 80}), 1);
  ASSERT_EQ(right.face, (CropFace{0, true}));
  // 2 px along the axis' screen direction is 1 mm; the perpendicular part is ignored.
  const glm::dvec2 along = glm::normalize(glm::dvec2(1, 1)), across(along.y, -along.x);
  EXPECT_NEAR(draggedCropBox(kBox, right, 8.0 * along + 5.0 * across, kExtent).maxMm.x, 54, 1e-9);
}

}  // namespace
}  // namespace angio
