// The centerline model: frames (physical LPS <-> volume frame), arc length and resampling, bounds,
// shared trunks, validation, and the phantom's ground truth inside its lumen.
#include "vessel/centerline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "phantom/phantom.h"
#include "core/voxel.h"

namespace angio {
namespace {

CenterlinePath straightPath(const std::string& name, glm::dvec3 from, glm::dvec3 to, int points,
                            double radiusFrom, double radiusTo) {
  CenterlinePath path{name, {}};
  for (int n = 0; n < points; ++n) {
    const double t = double(n) / (points - 1);
    path.points.push_back({glm::mix(from, to, t), radiusFrom + t * (radiusTo - radiusFrom)});
  }
  return path;
}

// A helix of radius 20 mm and pitch 30 mm per turn, `points` per turn, two turns.
CenterlinePath helix(int pointsPerTurn) {
  CenterlinePath path{"helix", {}};
  for (int n = 0; n <= 2 * pointsPerTurn; ++n) {
    const double angle = 2 * std::numbers::pi * n / pointsPerTurn;
    path.points.push_back({{20 * std::cos(angle), 20 * std::sin(angle), 30.0 * n / pointsPerTurn}, 3.0});
  }
  return path;
}

Centerlines withPaths(std::vector<CenterlinePath> paths) {
  Centerlines centerlines;
  centerlines.source = "test.vtp";
  centerlines.paths = std::move(paths);
  return centerlines;
}

// A volume stored like aorta.mha after reorientation can still carry a flipped placement; this
// one has direction diag(-1, -1, 1), as aorta.mha's header, and anisotropic spacing.
Volume flippedVolume() {
  Volume volume = makeVolume({20, 30, 10}, {0.5, 0.75, 2.0});
  volume.origin = {-100.0, -20.0, 5.0};
  volume.direction = glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1));
  return volume;
}

std::vector<std::string> problems(const std::vector<CenterlineIssue>& issues, IssueSeverity severity) {
  std::vector<std::string> found;
  for (const CenterlineIssue& issue : issues) {
    if (issue.severity == severity) found.push_back(issue.problem);
  }
  return found;
}

// --- Frames -------------------------------------------------------------------------------------

TEST(CenterlineFrames, VolumeFrameIsVoxelIndexTimesSpacing) {
  const Volume volume = flippedVolume();
  const glm::dvec3 index{3.0, 7.5, 2.25};
  const glm::dvec3 physical = indexToPhysical(volume, index);
  // physical = origin + direction * (index * spacing): x and y run backwards.
  EXPECT_NEAR(physical.x, -100.0 - 3.0 * 0.5, 1e-12);
  EXPECT_NEAR(physical.y, -20.0 - 7.5 * 0.75, 1e-12);
  const glm::dvec3 frame = volumeFrameMm(volume, physical);
  EXPECT_NEAR(frame.x, 1.5, 1e-12);
  EXPECT_NEAR(frame.y, 5.625, 1e-12);
  EXPECT_NEAR(frame.z, 4.5, 1e-12);
  EXPECT_EQ(nearestVoxelToPoint(volume, physical), glm::ivec3(3, 8, 2));
}

// An oblique acquisition keeps its residual rotation in `direction` (core/volume.h): 20 degrees
// about the patient's long axis here.
Volume obliqueVolume() {
  Volume volume = makeVolume({40, 40, 20}, {0.8, 0.8, 1.5});
  const double angle = 20.0 * std::numbers::pi / 180.0;
  volume.origin = {10.0, -30.0, 100.0};
  volume.direction = glm::dmat3(glm::dvec3(std::cos(angle), std::sin(angle), 0),
                                glm::dvec3(-std::sin(angle), std::cos(angle), 0), glm::dvec3(0, 0, 1));
  return volume;
}

TEST(CenterlineFrames, ToVolumeFrameMovesPointsKeepsRadiiAndLengths) {
  const Centerlines physical = withPaths({helix(24)});
  for (const Volume& volume : {flippedVolume(), obliqueVolume()}) {
    const Centerlines mapped = toVolumeFrame(physical, volume);
    EXPECT_EQ(mapped.frame, CenterlineFrame::volume);
    ASSERT_EQ(mapped.paths.size(), 1u);
    ASSERT_EQ(mapped.paths[0].points.size(), physical.paths[0].points.size());
    for (std::size_t n = 0; n < mapped.paths[0].points.size(); ++n) {
      const CenterlinePoint& before = physical.paths[0].points[n];
      const CenterlinePoint& after = mapped.paths[0].points[n];
      // Back through the volume's placement: index = frame / spacing, physical = origin + ...
      const glm::dvec3 back = indexToPhysical(volume, after.positionMm / volume.spacing);
      EXPECT_NEAR(glm::distance(back, before.positionMm), 0.0, 1e-9);
      EXPECT_EQ(after.radiusMm, before.radiusMm);
    }
    // The map is rigid (a rotation and a shift), so arc length does not change.
    EXPECT_NEAR(pathLengthMm(mapped.paths[0]), pathLengthMm(physical.paths[0]), 1e-9);
    EXPECT_THROW(toVolumeFrame(mapped, volume), std::logic_error);
  }
}

// --- Arc length and resampling ------------------------------------------------------------------

TEST(CenterlineGeometry, ArcLengthAccumulatesSegmentLengths) {
  CenterlinePath path{"p", {{{0, 0, 0}, 1}, {{3, 4, 0}, 1}, {{3, 4, 12}, 1}, {{3, 4, 12}, 1}}};
  EXPECT_EQ(arcLengthsMm(path), (std::vector<double>{0, 5, 17, 17}));
  EXPECT_EQ(pathLengthMm(path), 17);
  EXPECT_EQ(pathLengthMm(CenterlinePath{}), 0);
}

TEST(CenterlineGeometry, ResamplingAStraightPathGivesUniformStepsAndInterpolatedRadii) {
  const CenterlinePath path = straightPath("p", {0, 0, 0}, {10, 0, 0}, 3, 4.0, 2.0);
  const CenterlinePath resampled = resampleByArcLength(path, 3.0);
  ASSERT_EQ(resampled.points.size(), 5u);  // 0, 3, 6, 9 and the end point 10
  const double expectedX[] = {0, 3, 6, 9, 10};
  for (std::size_t n = 0; n < 5; ++n) {
    EXPECT_NEAR(resampled.points[n].positionMm.x, expectedX[n], 1e-12);
    EXPECT_NEAR(resampled.points[n].radiusMm, 4.0 - 0.2 * expectedX[n], 1e-12);
  }
  EXPECT_EQ(resampled.name, "p");
}

TEST(CenterlineGeometry, ResamplingKeepsEndpointsAndLengthOfACurvedPath) {
  const CenterlinePath path = helix(90);
  const double length = pathLengthMm(path);
  for (double step : {0.5, 1.0, 2.0}) {
    const CenterlinePath resampled = resampleByArcLength(path, step);
    EXPECT_EQ(resampled.points.front().positionMm, path.points.front().positionMm);
    EXPECT_EQ(resampled.points.back().positionMm, path.points.back().positionMm);
    EXPECT_NEAR(pathLengthMm(resampled), length, 0.01 * length) << step;
    const std::vector<double> arc = arcLengthsMm(resampled);
    // Steps along the chord are the arc-length step, up to the chord/arc difference.
    for (std::size_t n = 1; n + 1 < arc.size(); ++n) {
      EXPECT_NEAR(arc[n] - arc[n - 1], step, 0.01 * step) << step;
    }
    EXPECT_LE(arc.back() - arc[arc.size() - 2], step * 1.01);
  }
}

TEST(CenterlineGeometry, ResamplingSkipsRepeatedPointsAndLeavesDegeneratePathsAlone) {
  CenterlinePath repeated{"r", {{{0, 0, 0}, 1}, {{0, 0, 0}, 1}, {{0, 0, 4}, 3}, {{0, 0, 4}, 3}}};
  const CenterlinePath resampled = resampleByArcLength(repeated, 1.0);
  ASSERT_EQ(resampled.points.size(), 5u);
  EXPECT_NEAR(resampled.points[2].positionMm.z, 2.0, 1e-12);
  EXPECT_NEAR(resampled.points[2].radiusMm, 2.0, 1e-12);

  const CenterlinePath single{"s", {{{1, 2, 3}, 1}}};
  EXPECT_EQ(resampleByArcLength(single, 1.0).points.size(), 1u);
  const CenterlinePath still{"z", {{{1, 2, 3}, 1}, {{1, 2, 3}, 2}}};
  EXPECT_EQ(resampleByArcLength(still, 1.0).points.size(), 2u);
  for (double bad :
       {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(resampleByArcLength(single, bad), std::invalid_argument) << bad;
  }
}

// --- Bounds and shared trunks -------------------------------------------------------------------

TEST(CenterlineGeometry, BoundsHoldTheTubeOfTheLargestRadius) {
  CenterlinePath path{"p", {{{0, 0, 0}, 1}, {{10, -5, 2}, 3}, {{4, 8, -1}, 2}}};
  const BoxMm box = pathBounds(path);
  EXPECT_EQ(box.lo, glm::dvec3(-3, -8, -4));
  EXPECT_EQ(box.hi, glm::dvec3(13, 11, 5));
  const BoxMm empty = pathBounds(CenterlinePath{});
  EXPECT_GT(empty.lo.x, empty.hi.x);
  const std::vector<BoxMm> boxes = pathBounds(withPaths({path, path}));
  ASSERT_EQ(boxes.size(), 2u);
  EXPECT_EQ(boxes[1].hi, box.hi);
}

TEST(CenterlineGeometry, SharedPrefixIsTheCommonTrunk) {
  const CenterlinePath trunk = straightPath("t", {0, 0, 0}, {0, 0, 10}, 11, 5, 5);
  CenterlinePath left = trunk, right = trunk;
  left.points.push_back({{1, 0, 11}, 3});
  right.points.push_back({{-1, 0, 11}, 3});
  EXPECT_EQ(sharedPrefixLength(left, right), 11u);
  EXPECT_EQ(sharedPrefixLength(left, left), left.points.size());
  EXPECT_EQ(sharedPrefixLength(left, right, 2.5), 12u);  // the branch points are 2 mm apart
  right.points[0].positionMm.x += 0.1;
  EXPECT_EQ(sharedPrefixLength(left, right), 0u);
}

// --- Validation ---------------------------------------------------------------------------------

TEST(CenterlineValidation, GoodCenterlinesHaveNoIssues) {
  EXPECT_TRUE(validateCenterlines(withPaths({helix(12)})).empty());
}

TEST(CenterlineValidation, ErrorsNameThePath) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    CenterlinePath path;
    std::string expected;
  };
  const Case cases[] = {
      {{"empty", {}}, "path 'empty': has no points"},
      {{"nanx", {{{0, 0, 0}, 1}, {{nan, 0, 0}, 1}}}, "path 'nanx': point 1: coordinate is not finite"},
      {{"infz", {{{0, 0, inf}, 1}}}, "path 'infz': point 0: coordinate is not finite"},
      {{"nanr", {{{0, 0, 0}, nan}}}, "path 'nanr': point 0: radius is not finite"},
      {{"neg", {{{0, 0, 0}, 1}, {{0, 0, 1}, -0.5}}}, "path 'neg': point 1: negative radius"},
  };
  for (const Case& c : cases) {
    const Centerlines centerlines = withPaths({helix(12), c.path});
    const std::vector<CenterlineIssue> issues = validateCenterlines(centerlines);
    EXPECT_TRUE(hasError(issues)) << c.expected;
    EXPECT_EQ(problems(issues, IssueSeverity::error), std::vector<std::string>{c.expected});
    EXPECT_EQ(describe(centerlines, issues.front()), "test.vtp: " + c.expected);
  }
  const std::vector<CenterlineIssue> none = validateCenterlines(withPaths({}));
  EXPECT_EQ(problems(none, IssueSeverity::error),
            std::vector<std::string>{"contains no centerline paths"});
}

TEST(CenterlineValidation, SinglePointsAndZeroRadiiAreWarningsAndKept) {
  const Centerlines centerlines =
      withPaths({{"dot", {{{0, 0, 0}, 2}}}, {"thin", {{{0, 0, 0}, 0}, {{0, 0, 1}, 0}, {{0, 0, 2}, 1}}}});
  const std::vector<CenterlineIssue> issues = validateCenterlines(centerlines);
  EXPECT_FALSE(hasError(issues));
  EXPECT_EQ(problems(issues, IssueSeverity::warning),
            (std::vector<std::string>{"path 'dot': has a single point",
                                      "path 'thin': 2 of 3 points have radius 0 (unknown)"}));
}

TEST(CenterlineValidation, PointsOutsideTheVolumeAreCountedPerPath) {
  const Volume volume = flippedVolume();
  CenterlinePath inside{"inside", {}}, partly{"partly", {}};
  for (int j = 0; j < 30; j += 3) {
    inside.points.push_back({indexToPhysical(volume, {10, j, 5}), 1});
  }
  // Voxel cells reach half a voxel beyond the centres: -0.4 is in, -0.6 and 30.5 are out.
  partly.points = {{indexToPhysical(volume, {-0.4, 0, 0}), 1},
                   {indexToPhysical(volume, {-0.6, 0, 0}), 1},
                   {indexToPhysical(volume, {5, 30.5, 0}), 1},
                   {indexToPhysical(volume, {5, 5, 9.4}), 1}};
  const Centerlines physical = withPaths({inside, partly});
  const std::vector<std::string> expected = {"path 'partly': 2 of 4 points lie outside the volume"};
  EXPECT_EQ(problems(checkInsideVolume(physical, volume), IssueSeverity::warning), expected);
  EXPECT_FALSE(hasError(checkInsideVolume(physical, volume)));
  // The same answer from the volume frame.
  EXPECT_EQ(problems(checkInsideVolume(toVolumeFrame(physical, volume), volume), IssueSeverity::warning),
            expected);
}

// --- The phantom's ground truth -----------------------------------------------------------------

TEST(CenterlinePhantom, PathsInTheVolumeFrameLieInsideTheLumen) {
  // 128 x 128 x 300 (3.2 x 3.2 x 4 mm voxels): as in the phantom's own test, partial volume lifts
  // >= 95% of the nearest voxels of each path into the lumen range.
  const Phantom phantom =
      generatePhantom({.dims = {128, 128, 300}, .seed = 1, .style = PhantomStyle::simple});
  const Centerlines physical = phantom.centerlines;
  EXPECT_FALSE(hasError(validateCenterlines(physical)));
  EXPECT_TRUE(checkInsideVolume(physical, phantom.volume).empty());
  const Centerlines framed = toVolumeFrame(physical, phantom.volume);
  const Volume& volume = phantom.volume;
  for (const CenterlinePath& path : framed.paths) {
    std::size_t inLumen = 0;
    for (const CenterlinePoint& point : path.points) {
      const glm::ivec3 voxel(glm::floor(point.positionMm / volume.spacing + 0.5));
      ASSERT_TRUE(glm::all(glm::greaterThanEqual(voxel, glm::ivec3(0))) &&
                  glm::all(glm::lessThan(voxel, volume.dims)))
          << path.name;
      const double hu = huOfDensity(volume.densityAt(voxel.x, voxel.y, voxel.z));
      inLumen += hu >= 150 && hu <= 700;
    }
    EXPECT_GE(double(inLumen) / path.points.size(), 0.95) << path.name;
    // Resampled at 1 mm the trunk and every branch keep their length.
    const CenterlinePath resampled = resampleByArcLength(path, 1.0);
    EXPECT_NEAR(pathLengthMm(resampled), pathLengthMm(path), 0.01 * pathLengthMm(path));
  }
  // The phantom repeats the aorta in every path: the first two share a trunk.
  ASSERT_GE(framed.paths.size(), 2u);
  const std::size_t trunk = sharedPrefixLength(framed.paths[0], framed.paths[1]);
  EXPECT_GT(trunk, 10u);
  EXPECT_LT(trunk, framed.paths[0].points.size());
}

}  // namespace
}  // namespace angio
