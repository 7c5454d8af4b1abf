// Transfer function: piecewise-linear evaluation, the 4096-entry table, the integrated-opacity
// visibility query (thesis sec. 4.2.2) and the safe modulators.
#include "core/transfer_function.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace angio {
namespace {

ControlPoint point(double hu, glm::vec3 color, double opacity) { return {hu, color, opacity}; }

TransferFunction rampTf() {
  TransferFunction tf;
  tf.points = {point(0, {0.f, 0.f, 0.f}, 0.0), point(100, {1.f, 0.5f, 0.f}, 0.4),
               point(300, {0.f, 1.f, 1.f}, 0.8)};
  return tf;
}

// Random TF with `count` points; opacities are 0 with probability 1/3 so there are invisible
// stretches, and `tinyOpacity` replaces some visible opacities to test the exact visibility count.
TransferFunction randomTf(std::mt19937& rng, int count, double tinyOpacity) {
  std::uniform_real_distribution<double> hu(-1024, 3071), unit(0, 1);
  std::uniform_int_distribution<int> kind(0, 2);
  TransferFunction tf;
  for (int i = 0; i < count; ++i) {
    const int k = kind(rng);
    const double opacity = k == 0 ? 0.0 : k == 1 ? tinyOpacity : unit(rng);
    tf.points.push_back(point(hu(rng), {float(unit(rng)), float(unit(rng)), float(unit(rng))}, opacity));
  }
  sortPoints(tf);
  return tf;
}

// The documented meaning of anyVisible: a reversed range is empty; otherwise both ends are
// clamped to the table and every density in between is looked at. Returns the largest opacity
// in the range (> 0 iff visible).
float maxOpacityIn(const TfTable& table, int lo, int hi) {
  if (hi < lo) return 0.f;
  lo = std::clamp(lo, 0, kDensityLevels - 1);
  hi = std::clamp(hi, 0, kDensityLevels - 1);
  float maxOpacity = 0.f;
  for (int d = lo; d <= hi; ++d) maxOpacity = std::max(maxOpacity, table.rgba[d].a);
  return maxOpacity;
}

TEST(TransferFunction, InterpolatesLinearlyBetweenPoints) {
  const TransferFunction tf = rampTf();
  const glm::vec4 at50 = evaluate(tf, 50);
  EXPECT_FLOAT_EQ(at50.r, 0.5f);
  EXPECT_FLOAT_EQ(at50.g, 0.25f);
  EXPECT_FLOAT_EQ(at50.b, 0.f);
  EXPECT_FLOAT_EQ(at50.a, 0.2f);
  const glm::vec4 at250 = evaluate(tf, 250);  // 3/4 of the way from 100 to 300
  EXPECT_FLOAT_EQ(at250.r, 0.25f);
  EXPECT_FLOAT_EQ(at250.g, 0.875f);
  EXPECT_FLOAT_EQ(at250.b, 0.75f);
  EXPECT_FLOAT_EQ(at250.a, 0.7f);
  EXPECT_FLOAT_EQ(evaluate(tf, 100).a, 0.4f);  // exactly on a control point
}

TEST(TransferFunction, IsConstantBeyondTheEndPoints) {
  const TransferFunction tf = rampTf();
  EXPECT_EQ(evaluate(tf, -1024), evaluate(tf, 0));
  EXPECT_EQ(evaluate(tf, -500), glm::vec4(0.f));
  EXPECT_EQ(evaluate(tf, 3071), glm::vec4(0.f, 1.f, 1.f, 0.8f));
  EXPECT_EQ(evaluate(tf, 1000), evaluate(tf, 300));
}

TEST(TransferFunction, EmptyIsTransparentBlack) {
  const TransferFunction empty;
  EXPECT_EQ(evaluate(empty, 300), glm::vec4(0.f));
  const TfTable table = buildTable(empty);
  for (int d = 0; d < kDensityLevels; ++d) ASSERT_EQ(table.rgba[d], glm::vec4(0.f)) << d;
  EXPECT_FALSE(table.anyVisible(0, kDensityLevels - 1));
  EXPECT_EQ(table.integratedOpacity[kDensityLevels], 0.0);
}

TEST(TransferFunction, StepAtDuplicateHuIsSharp) {
  TransferFunction tf;
  tf.points = {point(200, {0.f, 0.f, 0.f}, 0.0), point(200, {1.f, 1.f, 1.f}, 1.0)};
  EXPECT_EQ(evaluate(tf, 199.5).a, 0.f);
  EXPECT_EQ(evaluate(tf, 200.5).a, 1.f);
}

TEST(TransferFunctionTable, MatchesPointwiseEvaluationAtEveryDensity) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 5; ++trial) {
    TransferFunction tf = randomTf(rng, 2 + trial * 3, 0.3);
    tf.modulators = {0.5 + trial * 0.4, trial * 37.0 - 50};
    const TfTable table = buildTable(tf);
    for (int d = 0; d < kDensityLevels; ++d)
      ASSERT_EQ(table.rgba[d], evaluate(tf, huOfDensity(d))) << "trial " << trial << " d " << d;
  }
}

TEST(TransferFunctionTable, AgreesWithIndependentInterpolationAtKnownDensities) {
  // Recomputes the ramp by hand in double: density d is HU d - 1024.
  const TfTable table = buildTable(rampTf());
  for (int hu = -1024; hu <= 3071; hu += 7) {
    const double expected = hu <= 0     ? 0.0
                            : hu <= 100 ? 0.4 * hu / 100
                            : hu <= 300 ? 0.4 + 0.4 * (hu - 100) / 200
                                        : 0.8;
    ASSERT_NEAR(table.rgba[hu + kHuOffset].a, expected, 1e-6) << hu;
  }
}

TEST(TransferFunctionTable, SortsUnsortedPoints) {
  TransferFunction shuffled = rampTf();
  std::swap(shuffled.points[0], shuffled.points[2]);
  const TfTable fromShuffled = buildTable(shuffled);
  const TfTable fromSorted = buildTable(rampTf());
  for (int d = 0; d < kDensityLevels; ++d) ASSERT_EQ(fromShuffled.rgba[d], fromSorted.rgba[d]);
}

TEST(TransferFunctionTable, IntegratedOpacityIsThePrefixSum) {
  std::mt19937 rng(11);
  const TfTable table = buildTable(randomTf(rng, 8, 0.2));
  double sum = 0;
  for (int d = 0; d < kDensityLevels; ++d) {
    ASSERT_NEAR(table.integratedOpacity[d], sum, 1e-9 * (1 + sum)) << d;
    sum += table.rgba[d].a;
  }
  EXPECT_NEAR(table.integratedOpacity[kDensityLevels], sum, 1e-9 * (1 + sum));
}

TEST(TransferFunctionTable, AnyVisibleMatchesBruteForceOnRandomRanges) {
  std::mt19937 rng(2024);
  std::uniform_int_distribution<int> density(-50, kDensityLevels + 50);
  std::uniform_int_distribution<int> shortLength(0, 40);
  const double tinyOpacities[] = {0.5, 1e-30, 1e-30, 1e-7, 1e-30};
  int visible = 0, hidden = 0, onlyTinyVisible = 0;
  for (int trial = 0; trial < 5; ++trial) {
    const TfTable table = buildTable(randomTf(rng, 3 + 2 * trial, tinyOpacities[trial]));
    for (int query = 0; query < 4000; ++query) {
      int lo = density(rng);
      // Half the queries are short ranges, where visible and invisible answers both occur.
      int hi = query % 2 == 0 ? lo + shortLength(rng) : density(rng);
      if (query % 7 == 0) std::swap(lo, hi);  // empty (reversed) ranges too
      const float maxOpacity = maxOpacityIn(table, lo, hi);
      ASSERT_EQ(table.anyVisible(lo, hi), maxOpacity > 0.f)
          << "trial " << trial << " [" << lo << ", " << hi << "]";
      (maxOpacity > 0.f ? visible : hidden)++;
      if (maxOpacity > 0.f && maxOpacity < 1e-20f) onlyTinyVisible++;
    }
  }
  // The random ranges really exercise both answers and the tiny-opacity case.
  EXPECT_GT(visible, 1000);
  EXPECT_GT(hidden, 1000);
  EXPECT_GT(onlyTinyVisible, 50);
}

TEST(TransferFunctionTable, AnyVisibleFindsASingleTinyVisibleDensity) {
  // Only HU 500 has opacity, 1e-30, and it comes after an opaque stretch at low HU: a
  // floating-point prefix sum (~125 there) cannot see it, the integer visibility count must.
  TransferFunction tf;
  tf.points = {point(-1024, {1.f, 1.f, 1.f}, 1.0), point(-900, {1.f, 1.f, 1.f}, 1.0),
               point(-899, {1.f, 1.f, 1.f}, 0.0),  point(499, {1.f, 1.f, 1.f}, 0.0),
               point(500, {1.f, 1.f, 1.f}, 1e-30), point(501, {1.f, 1.f, 1.f}, 0.0),
               point(2000, {1.f, 1.f, 1.f}, 0.0),  point(2001, {1.f, 1.f, 1.f}, 1.0)};
  const TfTable table = buildTable(tf);
  const int spike = densityOfHu(500);
  ASSERT_GT(table.rgba[spike].a, 0.f);
  EXPECT_EQ(table.rgba[spike - 1].a, 0.f);
  EXPECT_EQ(table.rgba[spike + 1].a, 0.f);
  EXPECT_TRUE(table.anyVisible(spike, spike));
  EXPECT_TRUE(table.anyVisible(spike - 10, spike));
  EXPECT_TRUE(table.anyVisible(spike, spike + 10));
  EXPECT_FALSE(table.anyVisible(spike - 10, spike - 1));
  EXPECT_FALSE(table.anyVisible(spike + 1, densityOfHu(2000)));
  EXPECT_TRUE(table.anyVisible(densityOfHu(2001), densityOfHu(2001)));
  // The prefix sum of opacity indeed cannot resolve the spike, which is why the count exists.
  EXPECT_EQ(table.integratedOpacity[spike + 1] - table.integratedOpacity[spike], 0.0);
}

TEST(TransferFunctionTable, AnyVisibleClampsToTheTable) {
  TransferFunction tf;
  tf.points = {point(3070, {1.f, 1.f, 1.f}, 0.0), point(3071, {1.f, 1.f, 1.f}, 0.5)};
  const TfTable table = buildTable(tf);
  EXPECT_TRUE(table.anyVisible(4000, 99999));
  EXPECT_TRUE(table.anyVisible(5000, 6000));  // beyond the table: clamped to density 4095
  EXPECT_FALSE(table.anyVisible(-100, 4000));
  EXPECT_FALSE(table.anyVisible(5000, 4096));  // reversed: empty, even though both clamp to 4095
}

TEST(TfModulators, OpacityScaleScalesAndClamps) {
  TransferFunction tf = rampTf();
  tf.modulators.opacityScale = 0.5;
  EXPECT_FLOAT_EQ(evaluate(tf, 50).a, 0.1f);
  EXPECT_FLOAT_EQ(evaluate(tf, 300).a, 0.4f);
  tf.modulators.opacityScale = 2.0;
  EXPECT_FLOAT_EQ(evaluate(tf, 50).a, 0.4f);
  EXPECT_FLOAT_EQ(evaluate(tf, 300).a, 1.0f);                 // 1.6 clamped
  EXPECT_FLOAT_EQ(evaluate(tf, 200).a, 1.0f);                 // 1.2 clamped
  EXPECT_EQ(evaluate(tf, 200).r, evaluate(rampTf(), 200).r);  // color untouched
  tf.modulators.opacityScale = 0.0;
  EXPECT_FALSE(buildTable(tf).anyVisible(0, kDensityLevels - 1));
}

TEST(TfModulators, HuShiftMovesTheCurve) {
  const TransferFunction original = rampTf();
  for (const double shift : {-200.0, -13.0, 0.0, 55.0, 400.0}) {
    TransferFunction shifted = original;
    shifted.modulators.huShift = shift;
    for (double hu = -300; hu <= 600; hu += 12.5)
      ASSERT_EQ(evaluate(shifted, hu + shift), evaluate(original, hu)) << shift << " " << hu;
  }
  TransferFunction shifted = original;
  shifted.modulators.huShift = 100;
  const TfTable table = buildTable(shifted);
  EXPECT_EQ(table.rgba[densityOfHu(100)].a, 0.f);  // old start point moved from 0 to 100 HU
  EXPECT_FLOAT_EQ(table.rgba[densityOfHu(200)].a, 0.4f);
}

}  // namespace
}  // namespace angio
