// Ray against a round cone (tapered capsule), checked against point sampling with an independent
// membership test: p is inside when min over s of |p - c(s)| - r(s) <= 0, a convex function of s
// minimised by ternary search.
#include "vessel/capsule_intersection.h"

#include <gtest/gtest.h>

#include "tests/vessel/tube_distance.h"

#include <cmath>
#include <random>

namespace angio {
namespace {

double signedDistance(const RoundCone& cone, glm::dvec3 p) {
  return test_support::taperedSegmentSignedDistance(cone.centre0, cone.radius0, cone.centre1,
                                                    cone.radius1, p);
}

// Every sample along the ray is inside the span exactly when it is inside the cone (samples
// within `tolerance` of the surface are not judged).
void expectMatchesSampling(const RoundCone& cone, glm::dvec3 origin, glm::dvec3 direction) {
  constexpr double kTolerance = 1e-6;
  const DepthSpan span = RoundConeIntersector(cone, direction).intersect(origin);
  int inside = 0;
  for (double t = -60; t <= 60; t += 0.02) {
    const double distance = signedDistance(cone, origin + t * direction);
    if (std::abs(distance) < kTolerance) continue;
    const bool inSpan = !span.empty() && span.begin <= t && t <= span.end;
    inside += distance < 0;
    ASSERT_EQ(inSpan, distance < 0) << "t = " << t << ", distance " << distance << ", span ["
                                    << span.begin << ", " << span.end << "]";
  }
  if (inside == 0) {
    EXPECT_TRUE(span.empty() || span.end - span.begin < 0.04);
  }
}

TEST(RoundConeIntersector, CylinderAcrossItsAxisGivesTheChord) {
  const RoundCone cone{{0, 0, -10}, {0, 0, 10}, 3, 3};
  const DepthSpan span = RoundConeIntersector(cone, {0, 1, 0}).intersect({1, -20, 2});
  EXPECT_NEAR(span.begin, 20 - std::sqrt(8.0), 1e-12);
  EXPECT_NEAR(span.end, 20 + std::sqrt(8.0), 1e-12);
}

TEST(RoundConeIntersector, AlongTheAxisReachesThroughBothCaps) {
  const RoundCone cone{{0, 0, -10}, {0, 0, 10}, 3, 1};
  const DepthSpan span = RoundConeIntersector(cone, {0, 0, 1}).intersect({0, 0, -30});
  EXPECT_NEAR(span.begin, 30 - 10 - 3, 1e-12);
  EXPECT_NEAR(span.end, 30 + 10 + 1, 1e-12);
}

TEST(RoundConeIntersector, MissesWhenFartherThanTheRadius) {
  const RoundCone cone{{0, 0, -10}, {0, 0, 10}, 3, 3};
  EXPECT_TRUE(RoundConeIntersector(cone, {0, 1, 0}).intersect({3.01, 0, 0}).empty());
  EXPECT_TRUE(RoundConeIntersector(cone, {0, 1, 0}).intersect({0, 0, 13.01}).empty());
}

TEST(RoundConeIntersector, BallInsideTheOtherIsTheBiggerBall) {
  const RoundCone cone{{0, 0, 0}, {1, 0, 0}, 5, 2};
  const DepthSpan span = RoundConeIntersector(cone, {0, 0, 1}).intersect({3, 0, -10});
  EXPECT_NEAR(span.begin, 10 - 4, 1e-12);
  EXPECT_NEAR(span.end, 10 + 4, 1e-12);
}

TEST(RoundConeIntersector, MatchesPointSamplingForRandomConesAndRays) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-12, 12), radius(0, 6);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 150; ++trial) {
    const RoundCone cone{{coordinate(random), coordinate(random), coordinate(random)},
                         {coordinate(random), coordinate(random), coordinate(random)},
                         radius(random),
                         radius(random)};
    glm::dvec3 direction(normal(random), normal(random), normal(random));
    direction = glm::normalize(direction);
    // Aim near the cone so that most rays hit.
    const glm::dvec3 target = glm::mix(cone.centre0, cone.centre1, 0.5) +
                              glm::dvec3(normal(random), normal(random), normal(random)) * 4.0;
    expectMatchesSampling(cone, target - 40.0 * direction, direction);
    if (testing::Test::HasFatalFailure()) return;
  }
}

TEST(RoundConeIntersector, MatchesPointSamplingForRaysParallelToTheAxisOrAGenerator) {
  const RoundCone cone{{0, 0, -8}, {0, 0, 8}, 4, 2};
  const glm::dvec3 axis(0, 0, 1);
  // sin(alpha) = (4 - 2) / 16: a generator makes angle alpha with the axis.
  const double alpha = std::asin(2.0 / 16);
  const glm::dvec3 generator(-std::sin(alpha), 0, std::cos(alpha));
  for (double offset : {0.0, 1.0, 2.5, 3.9, 4.1}) {
    expectMatchesSampling(cone, {offset, 0, -30}, axis);
    expectMatchesSampling(cone, glm::dvec3(offset, 0, 0) - 30.0 * generator, generator);
  }
}

// The per-row form for rays along +z gives the same spans as the general one.
TEST(DepthRayRoundCone, AgreesWithTheGeneralIntersector) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> coordinate(-12, 12), radius(0, 6);
  int hits = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const RoundCone cone{{coordinate(random), coordinate(random), coordinate(random)},
                         {coordinate(random), coordinate(random), coordinate(random)},
                         radius(random),
                         radius(random)};
    const RoundConeIntersector general(cone, {0, 0, 1});
    const DepthRayRoundCone withEndBall(cone, true), withoutEndBall(cone, false);
    const double h = coordinate(random), v = coordinate(random);
    const DepthSpan expected = general.intersect({h, v, 0});
    // Parts only where the row says they can reach.
    const DepthRayRoundCone::Row row = withEndBall.row(v);
    DepthSpan span;
    for (int p = 0; p < row.partCount; ++p) {
      const DepthRayRoundCone::RowPart& part = row.parts[p];
      if (h < part.hLo || h > part.hHi) continue;
      withEndBall.addPartSpans(row, part, h, 0, 1, &span);
    }
    ASSERT_EQ(span.empty(), expected.empty()) << "trial " << trial;
    if (expected.empty()) continue;
    ++hits;
    EXPECT_NEAR(span.begin, expected.begin, 1e-9);
    EXPECT_NEAR(span.end, expected.end, 1e-9);
    // Without the end ball: inside the full piece.
    const DepthSpan part = withoutEndBall.intersect(withoutEndBall.row(v), h);
    if (!part.empty()) {
      EXPECT_GE(part.begin, expected.begin - 1e-9);
      EXPECT_LE(part.end, expected.end + 1e-9);
    }
  }
  EXPECT_GT(hits, 3000);
}

TEST(DepthRayRoundCone, WithoutTheEndBallLeavesOnlyThatBall) {
  const RoundCone cone{{0, 0, 0}, {10, 0, 0}, 2, 2};
  const DepthRayRoundCone piece(cone, false);
  EXPECT_TRUE(piece.intersect(piece.row(0), 11.5).empty());   // only in the end ball
  EXPECT_FALSE(piece.intersect(piece.row(0), 9.5).empty());   // in the frustum
  EXPECT_FALSE(piece.intersect(piece.row(0), -1.5).empty());  // in the first ball
}

}  // namespace
}  // namespace angio
