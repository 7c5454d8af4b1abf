// The first level's sampling while dragging: the finest isd of the ladder from the medium level to
// four times the fast level's whose predicted time (the measured one times the pixel ratio) fits the
// budget.
#include "render/motion_sampling.h"

#include <gtest/gtest.h>

#include <cmath>

namespace angio {
namespace {

constexpr double kStep = 1.189207115002721;  // 2^(1/4)

TEST(MotionSampling, WithoutAMeasurementOrABudgetItIsTheFastLevel) {
  const LevelSamplings levels = defaultLevelSamplings();
  EXPECT_EQ(motionSampling(levels, std::nullopt, 40), levels[0]);
  EXPECT_EQ(motionSampling(levels, MeasuredFrame{5, 3}, 0), levels[0]);
}

TEST(MotionSampling, ACheapFastFrameRefinesToTheFinestStepWithinThreeQuartersOfTheBudget) {
  const LevelSamplings levels = defaultLevelSamplings();  // isd 1 (medium) .. 3 (fast)
  // 10 ms at isd 3: isd s costs 90 / s^2 ms; finer steps need <= 30 ms, so s^2 >= 3: 2.0
  // (kStep^3 = 1.68 would cost 31.8 ms).
  const Sampling refined = motionSampling(levels, MeasuredFrame{10, 3}, 40);
  EXPECT_NEAR(refined.isd, kStep * kStep * kStep * kStep, 1e-12);
  EXPECT_EQ(refined.osd, levels[0].osd);  // only the image sampling changes
  EXPECT_EQ(refined.filter, levels[0].filter);
  // Very cheap: the medium level's isd, never finer.
  EXPECT_DOUBLE_EQ(motionSampling(levels, MeasuredFrame{0.5, 3}, 40).isd, 1.0);
}

TEST(MotionSampling, ASlowFrameCoarsensToTheFirstStepWithinTheBudget) {
  const LevelSamplings levels = defaultLevelSamplings();
  // 100 ms at isd 1: kStep^3 costs 100 / 2.83 = 35.4 ms <= 40.
  EXPECT_NEAR(motionSampling(levels, MeasuredFrame{100, 1}, 40).isd, kStep * kStep * kStep, 1e-12);
}

TEST(MotionSampling, AFastLevelOverBudgetCoarsensPastItUpToFourTimesItsIsd) {
  const LevelSamplings levels = defaultLevelSamplings();  // fast: isd 3
  // 52 ms at isd 3 (the fast level on a tall run-off): 3 kStep costs 52 / 1.41 = 36.8 ms.
  EXPECT_NEAR(motionSampling(levels, MeasuredFrame{52, 3}, 40).isd, 3 * kStep, 1e-12);
  // 500 ms at isd 1: 3 kStep costs 500 / 12.7 = 39.3 ms.
  EXPECT_NEAR(motionSampling(levels, MeasuredFrame{500, 1}, 40).isd, 3 * kStep, 1e-12);
  // 2000 ms at isd 1 (a 1024-matrix run-off at the medium level): 3 kStep^5 costs 2000 / 50.9 =
  // 39.3 ms.
  EXPECT_NEAR(motionSampling(levels, MeasuredFrame{2000, 1}, 40).isd, 3 * std::pow(kStep, 5), 1e-9);
  // Even isd 12 (a sixteenth of the fast level's pixels) is over budget: it is the coarsest there is.
  EXPECT_NEAR(motionSampling(levels, MeasuredFrame{10000, 1}, 40).isd, 12.0, 1e-9);
  EXPECT_EQ(motionSampling(levels, MeasuredFrame{10000, 1}, 40).osd, levels[0].osd);
}

TEST(MotionSampling, LevelsWithoutRoomBelowTheFastLevelStillCoarsen) {
  LevelSamplings levels = defaultLevelSamplings();
  levels[int(Quality::medium)].isd = levels[int(Quality::fast)].isd;  // a zoom clamped both
  EXPECT_NEAR(motionSampling(levels, MeasuredFrame{78, 3}, 40).isd, 3 * kStep * kStep, 1e-12);
  EXPECT_DOUBLE_EQ(motionSampling(levels, MeasuredFrame{10, 3}, 40).isd, 3.0);
}

TEST(MotionSampling, AFrameJustWithinTheBudgetStaysWhereItIs) {
  const LevelSamplings levels = defaultLevelSamplings();
  const double isd = kStep * kStep * kStep * kStep;
  // 38 ms: the finer step would take 53.7 ms; the same step is within 40.
  EXPECT_NEAR(motionSampling(levels, MeasuredFrame{38, isd}, 40).isd, isd, 1e-12);
  // 25 ms: the finer step's 35.4 ms is within the budget but not within 3/4 of it.
  EXPECT_NEAR(motionSampling(levels, MeasuredFrame{25, isd}, 40).isd, isd, 1e-12);
}

}  // namespace
}  // namespace angio
