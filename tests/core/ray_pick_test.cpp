// The 3-D pick: the point where the rendering model's ray through an image point reaches
// opacity 0.5 (DVR) or its maximum (MIP), checked against analytic cases.
#include "core/ray_pick.h"

#include <gtest/gtest.h>

#include "core/view_geometry.h"

namespace angio {
namespace {

// 33^3 voxels of 1 mm: air with a cube of 0 HU over indices [10, 22] on every axis.
Volume cubeVolume(int label = 0) {
  Volume volume = makeVolume({33, 33, 33}, {1, 1, 1});
  for (int k = 10; k <= 22; ++k)
    for (int j = 10; j <= 22; ++j)
      for (int i = 10; i <= 22; ++i) volume.voxels[volume.indexOf(i, j, k)] = encodeVoxel(0, label);
  return volume;
}

// Opacity 0.2 per voxel unit above -500 HU, nothing below.
TfTable softTf() {
  TransferFunction tf;
  tf.points = {
      {-1024, {1, 1, 1}, 0}, {-501, {1, 1, 1}, 0}, {-500, {1, 1, 1}, 0.2}, {3071, {1, 1, 1}, 0.2}};
  return buildTable(tf);
}

RenderParams nearestView(double angle) {
  RenderParams p;
  p.angleDeg = angle;
  p.sampling = {1.0, 1.0, Filter::nearest, 0.98};
  return p;
}

// The image point of the pixel whose ray runs through voxel column (i, k) at theta = 0.
glm::dvec2 imagePointOver(const Volume& volume, const RenderParams& p, double i, double k) {
  const ViewGeometry view = makeViewGeometry(volume, p);
  return {i - view.centre.x + view.width * 0.5, view.height * 0.5 - (k - view.centre.z)};
}

TEST(RayPick, DvrPicksTheSampleWhereOpacityFirstReachesOneHalf) {
  // theta = 0 looks along +j; samples sit on voxel centres j = 16 + k. Front to back through the
  // cube: opacity 0.2, 0.36, 0.488, 0.590 at j = 10, 11, 12, 13: the pick is at j = 13.
  const Volume volume = cubeVolume();
  const TfTable table = softTf();
  const RenderParams p = nearestView(0);
  const auto picked = pickPoint(volume, singleTable(table), p, imagePointOver(volume, p, 16, 16));
  ASSERT_TRUE(picked);
  EXPECT_NEAR(picked->positionMm.x, 16, 1e-9);
  EXPECT_NEAR(picked->positionMm.y, 13, 1e-9);
  EXPECT_NEAR(picked->positionMm.z, 16, 1e-9);
  EXPECT_EQ(picked->density, float(densityOfHu(0)));
  // A lower threshold stops at the first sample in the cube; a ray beside it picks nothing.
  EXPECT_NEAR(
      pickPoint(volume, singleTable(table), p, imagePointOver(volume, p, 16, 16), 0.1)->positionMm.y, 10,
      1e-9);
  EXPECT_FALSE(pickPoint(volume, singleTable(table), p, imagePointOver(volume, p, 5, 16)));
}

TEST(RayPick, TheViewAngleTurnsTheRay) {
  // theta = 90 about k looks along -i (d = -e_b with b = i): the cube's face at i = 22 comes first.
  const Volume volume = cubeVolume();
  const TfTable table = softTf();
  const RenderParams p = nearestView(90);
  const ViewGeometry view = makeViewGeometry(volume, p);
  const auto picked = pickPoint(volume, singleTable(table), p, {view.width * 0.5, view.height * 0.5});
  ASSERT_TRUE(picked);
  EXPECT_NEAR(picked->positionMm.x, 19, 1e-9);  // 22, 21, 20, 19: the fourth sample
  EXPECT_NEAR(picked->positionMm.y, 16, 1e-9);
}

TEST(RayPick, MipPicksTheMaximum) {
  Volume volume = makeVolume({33, 33, 33}, {1, 1, 1}, encodeVoxel(0));
  volume.voxels[volume.indexOf(20, 12, 16)] = encodeVoxel(900);
  volume.voxels[volume.indexOf(20, 25, 16)] = encodeVoxel(400);
  RenderParams p = nearestView(0);
  p.compositing = Compositing::mip;
  const TfTable table = softTf();
  const auto picked = pickPoint(volume, singleTable(table), p, imagePointOver(volume, p, 20, 16));
  ASSERT_TRUE(picked);
  EXPECT_NEAR(picked->positionMm.y, 12, 1e-9);
  EXPECT_EQ(picked->density, float(densityOfHu(900)));
}

TEST(RayPick, AHiddenLabelIsPickedThrough) {
  const Volume volume = cubeVolume(1);
  const TfTable table = softTf();
  const LabelTables hideCube({{1, "cube", LabelMode::hidden, {}, {1, 1, 1}}});
  const RenderParams p = nearestView(0);
  EXPECT_FALSE(pickPoint(volume, {nullptr, nullptr, nullptr, &table, &hideCube}, p,
                         imagePointOver(volume, p, 16, 16)));
  EXPECT_TRUE(pickPoint(volume, singleTable(table), p, imagePointOver(volume, p, 16, 16)));
}

TEST(RayPick, GiveBackPicksTheFirstLabelledVoxelEvenWhenHidden) {
  const Volume volume = cubeVolume(2);
  const RenderParams p = nearestView(0);
  const auto picked = pickLabelled(volume, p, imagePointOver(volume, p, 16, 16));
  ASSERT_TRUE(picked);
  EXPECT_NEAR(picked->positionMm.y, 10, 1e-9);  // the cube's front face
  EXPECT_FALSE(pickLabelled(cubeVolume(0), p, imagePointOver(volume, p, 16, 16)));
}

}  // namespace
}  // namespace angio
