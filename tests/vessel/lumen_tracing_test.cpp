// Tracing on synthetic tubes with known geometry: two separate tubes are never joined, a tube's
// centre and radius are found to a fraction of a voxel (also through a stenosis and past a
// calcified plaque), a tree's trunk is shared point for point, cancel stops the field.
#include <atomic>
#include <cmath>

#include <gtest/gtest.h>

#include "core/volume.h"
#include "vessel/centerline_comparison.h"
#include "vessel/lumen_paths.h"
#include "vessel/vessel_tracing.h"

namespace angio {
namespace {

constexpr double kSpacingMm = 0.8;
constexpr double kTissueHu = 50, kLumenHu = 400, kCalciumHu = 1300;

struct Tube {
  glm::dvec3 from, to;  // volume frame, mm
  double radiusMm;
  double hu = kLumenHu;
};

double distanceToSegment(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b) {
  const glm::dvec3 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(p - (a + t * ab));
}

// Tubes in tissue, the wall a linear ramp one voxel wide (the scanner's blur), like the phantom;
// air in the row j = 0, as around a patient (the values look like calibrated HU).
Volume tubes(glm::ivec3 dims, const std::vector<Tube>& list) {
  Volume volume = makeVolume(dims, glm::dvec3(kSpacingMm), encodeVoxel(kTissueHu));
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        const glm::dvec3 p = glm::dvec3(i, j, k) * kSpacingMm;
        double hu = j == 0 ? -1000 : kTissueHu;
        for (const Tube& tube : list) {
          const double d = distanceToSegment(p, tube.from, tube.to);
          const double inside = std::clamp(0.5 - (d - tube.radiusMm) / kSpacingMm, 0.0, 1.0);
          hu = std::max(hu, kTissueHu + inside * (tube.hu - kTissueHu));
        }
        volume.voxels[volume.indexOf(i, j, k)] = encodeVoxel(hu);
      }
  return volume;
}

CenterlinePath straightPath(glm::dvec3 a, glm::dvec3 b, double radiusMm) {
  return {"truth", {{a, radiusMm}, {b, radiusMm}}};
}

TEST(LumenTracing, NeverJoinsTwoTubesThatContrastDoesNotJoin) {
  const glm::dvec3 a0(10, 12, 4), a1(10, 12, 44), b0(26, 12, 4), b1(26, 12, 44);
  const Volume volume = tubes({48, 32, 62}, {{a0, a1, 3.0}, {b0, b1, 3.0}});
  VesselTracer tracer(volume);
  const TracedPath path = tracer.trace({a0 + glm::dvec3(0, 0, 4), b1 - glm::dvec3(0, 0, 4)});
  EXPECT_FALSE(path.path);
  EXPECT_EQ(path.problem, "the points are not joined by contrast-filled lumen");
  // The tubes themselves are traced, each on its own.
  const TracedPath along = tracer.trace({a0 + glm::dvec3(0, 0, 4), a1 - glm::dvec3(0, 0, 4)});
  ASSERT_TRUE(along.path) << along.problem;
}

TEST(LumenTracing, FindsAnObliqueTubesCentreAndRadiusToAFractionOfAVoxel) {
  for (double radius : {1.5, 3.0, 8.0}) {
    const glm::dvec3 a(12 + radius, 12 + radius, 4), b(36 - radius, 30 - radius, 60);
    const Volume volume = tubes({60, 56, 82}, {{a, b, radius}});
    VesselTracer tracer(volume);
    const glm::dvec3 along = glm::normalize(b - a);
    // Clicks a radius and more from the ends: near a tube's rounded end the lumen's centre (the
    // largest inscribed sphere) lies a radius inside, where a click there snaps to.
    const double inset = radius + 2.0;
    const TracedPath traced = tracer.trace({a + inset * along, b - inset * along});
    ASSERT_TRUE(traced.path) << traced.problem;
    const CenterlineDeviation d = deviationFrom(*traced.path, straightPath(a, b, radius));
    EXPECT_LE(d.maxMm, 0.25 * kSpacingMm) << "radius " << radius;
    EXPECT_LE(d.meanRadiusError, 0.05) << "radius " << radius;
    // On the distance map's ridge (flat along a tube, up to voxel steps) a snapped end may move along
    // the axis by a voxel or two.
    EXPECT_NEAR(pathLengthMm(*traced.path), glm::length(b - a) - 2 * inset, 2.0) << "radius " << radius;
  }
}

TEST(LumenTracing, KeepsToTheCentreThroughAStenosisAndPastAPlaque) {
  // A 4 mm tube narrowed to 1.6 mm for 12 mm (between the rounded ends of the wide parts, which
  // reach 4 mm into the narrow one), and a calcified plaque on its wall further on.
  const glm::dvec3 a(20, 20, 4), b(20, 20, 76);
  const Tube narrowing{{20, 20, 26}, {20, 20, 46}, 1.6};
  std::vector<Tube> scene{{a, {20, 20, 26}, 4.0}, narrowing, {{20, 20, 46}, b, 4.0}};
  const Volume stenosis = tubes({50, 50, 100}, scene);
  VesselTracer tracer(stenosis);
  const TracedPath traced = tracer.trace({a + glm::dvec3(0, 0, 2), b - glm::dvec3(0, 0, 2)});
  ASSERT_TRUE(traced.path) << traced.problem;
  double narrowest = 100;
  for (const CenterlinePoint& p : traced.path->points) {
    EXPECT_LE(glm::length(glm::dvec2(p.positionMm) - glm::dvec2(20, 20)), 0.2) << p.positionMm.z;
    narrowest = std::min(narrowest, p.radiusMm);
  }
  EXPECT_NEAR(narrowest, 1.6, 0.3);

  // The plaque: a 2 mm ball of calcium centred on the wall at z = 60.
  scene.push_back({{24, 20, 60}, {24, 20, 60}, 2.0, kCalciumHu});
  const Volume plaque = tubes({50, 50, 100}, scene);
  VesselTracer plaqueTracer(plaque);
  const TracedPath past = plaqueTracer.trace({a + glm::dvec3(0, 0, 2), b - glm::dvec3(0, 0, 2)});
  ASSERT_TRUE(past.path) << past.problem;
  for (const CenterlinePoint& p : past.path->points) {
    // The plaque takes 2 mm of the lumen on one side: the centre moves away from it by about 1 mm
    // (the middle of what is left), never towards it.
    const double x = p.positionMm.x - 20;
    EXPECT_LE(x, 0.2) << p.positionMm.z;
    EXPECT_GE(x, -1.5) << p.positionMm.z;
  }
}

TEST(LumenTracing, ATreesPathsShareTheirTrunkPointForPoint) {
  // A Y: a trunk up the middle, two branches out of its top end.
  const glm::dvec3 root(30, 30, 4), fork(30, 30, 40), left(12, 30, 70), right(48, 30, 70);
  const Volume volume = tubes({76, 60, 92}, {{root, fork, 5.0}, {fork, left, 3.0}, {fork, right, 3.0}});
  VesselTracer tracer(volume);
  const TracedTree tree = tracer.traceDownstream(root + glm::dvec3(0, 0, 2));
  ASSERT_EQ(tree.centerlines.paths.size(), 2u) << tree.problem;
  const CenterlinePath& a = tree.centerlines.paths[0];
  const CenterlinePath& b = tree.centerlines.paths[1];
  const std::size_t shared = sharedPrefixLength(a, b);
  // The trunk is 36 mm long at 0.5 mm per point; it is shared up to two radii before the fork.
  EXPECT_GE(shared * 0.5, 36.0 - 2 * 5.0 - 4.0);
  EXPECT_LE(shared * 0.5, 36.0);
  for (const CenterlinePath* path : {&a, &b}) {
    const glm::dvec3 end = path->points.back().positionMm;
    const bool toLeft = glm::distance(end, left) < glm::distance(end, right);
    const CenterlinePath truth{"", {{root, 5.0}, {fork, 5.0}, {toLeft ? left : right, 3.0}}};
    EXPECT_LE(deviationFrom(*path, truth).meanMm, 0.5);
    EXPECT_LE(glm::distance(end, toLeft ? left : right), 5.0);  // to the end of the contrast
  }
  EXPECT_NE(glm::distance(a.points.back().positionMm, b.points.back().positionMm), 0.0);
}

TEST(LumenTracing, ACancelledFieldIsNotReady) {
  const Volume volume = tubes({40, 40, 40}, {{{16, 16, 4}, {16, 16, 28}, 3.0}});
  std::atomic<bool> cancel{true};
  const LumenField field(volume, {200, 800}, wholeVolume(volume), &cancel);
  EXPECT_FALSE(field.isReady());
  VesselTracer tracer(volume);
  EXPECT_EQ(tracer.trace({{16, 16, 8}, {16, 16, 24}}, &cancel).problem, "cancelled");
}

}  // namespace
}  // namespace angio
