#include "vessel/cross_section.h"

#include <cmath>

#include <gtest/gtest.h>

namespace angio {
namespace {

constexpr double kRadiusMm = 6;

// A cylinder of 400 HU (radius kRadiusMm) in -100 HU along `axis` (0 = i, 2 = k) through the
// middle of a 41^3 volume of 1 mm voxels.
Volume cylinderAlong(int axis) {
  Volume volume = makeVolume({41, 41, 41}, {1, 1, 1}, encodeVoxel(-100));
  for (int k = 0; k < 41; ++k)
    for (int j = 0; j < 41; ++j)
      for (int i = 0; i < 41; ++i) {
        const glm::dvec3 p(i - 20, j - 20, k - 20);
        const double r = axis == 2 ? std::hypot(p.x, p.y) : std::hypot(p.y, p.z);
        if (r <= kRadiusMm) volume.voxels[volume.indexOf(i, j, k)] = encodeVoxel(400);
      }
  return volume;
}

// The disc's area from the pixels above half way (150 HU), as the radius of a circle.
double discRadiusMm(const CrossSection& section) {
  int inside = 0;
  for (float hu : section.hu) inside += hu > 150;
  return std::sqrt(inside / M_PI) * section.pixelMm;
}

TEST(CrossSection, CylinderAlongItsAxisGivesADiscOfItsRadius) {
  const CrossSection section =
      sampleCrossSection(cylinderAlong(2), {20, 20, 20}, {0, 0, 1}, {0, 1, 0}, 30, 0.5);
  EXPECT_EQ(section.size % 2, 1);
  EXPECT_NEAR(discRadiusMm(section), kRadiusMm, 0.5);
  const int c = section.size / 2;
  EXPECT_NEAR(section.huAt(c, c), 400, 1);
  EXPECT_NEAR(section.huAt(0, 0), -100, 1);
}

TEST(CrossSection, OrientationFollowsTheTangent) {
  // Along i, a section normal to i is a disc; one normal to k (wrong tangent) cuts the cylinder
  // lengthwise: a band across the whole section, much more area than the disc.
  const Volume volume = cylinderAlong(0);
  const CrossSection across = sampleCrossSection(volume, {20, 20, 20}, {1, 0, 0}, {0, 0, 1}, 30, 0.5);
  const CrossSection lengthwise =
      sampleCrossSection(volume, {20, 20, 20}, {0, 0, 1}, {0, 1, 0}, 30, 0.5);
  EXPECT_NEAR(discRadiusMm(across), kRadiusMm, 0.5);
  EXPECT_GT(discRadiusMm(lengthwise), 1.5 * kRadiusMm);
  EXPECT_NEAR(glm::dot(across.uAxis, glm::dvec3(1, 0, 0)), 0, 1e-12);
  EXPECT_NEAR(glm::dot(across.vAxis, glm::dvec3(0, 0, 1)), 1, 1e-12);
  EXPECT_NEAR(glm::dot(glm::cross(across.uAxis, across.vAxis), glm::dvec3(1, 0, 0)), 1, 1e-12);
}

TEST(CrossSection, OutsideTheVolumeIsNotSampled) {
  const CrossSection section =
      sampleCrossSection(cylinderAlong(2), {0, 20, 20}, {0, 0, 1}, {0, 1, 0}, 20, 1);
  EXPECT_TRUE(std::isnan(section.huAt(0, section.size / 2)));
  EXPECT_FALSE(std::isnan(section.huAt(section.size - 1, section.size / 2)));
}

// An L: 20 mm along x, then 20 mm along z.
CenterlinePath elbow() {
  CenterlinePath path;
  for (const glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(10, 0, 0), glm::dvec3(20, 0, 0),
                             glm::dvec3(20, 0, 10), glm::dvec3(20, 0, 20)})
    path.points.push_back({p, 0});
  return path;
}

TEST(PlaceOnPath, InterpolatesByArcLengthAndTakesTheChordAboutThePointAsTangent) {
  const PathPlace straight = placeOnPath(elbow(), 5);
  EXPECT_NEAR(glm::distance(straight.pointMm, glm::dvec3(5, 0, 0)), 0, 1e-12);
  EXPECT_NEAR(glm::distance(straight.tangent, glm::dvec3(1, 0, 0)), 0, 1e-12);
  const PathPlace bend = placeOnPath(elbow(), 20);  // the corner: the chord runs diagonally
  EXPECT_NEAR(glm::distance(bend.pointMm, glm::dvec3(20, 0, 0)), 0, 1e-12);
  EXPECT_NEAR(glm::distance(bend.tangent, glm::normalize(glm::dvec3(1, 0, 1))), 0, 1e-12);
  const PathPlace past = placeOnPath(elbow(), 99);  // clamped to the end, looking along the path
  EXPECT_NEAR(glm::distance(past.pointMm, glm::dvec3(20, 0, 20)), 0, 1e-12);
  EXPECT_NEAR(glm::distance(past.tangent, glm::dvec3(0, 0, 1)), 0, 1e-12);
  EXPECT_NEAR(glm::distance(placeOnPath(elbow(), -3).pointMm, glm::dvec3(0.0)), 0, 1e-12);
}

}  // namespace
}  // namespace angio
