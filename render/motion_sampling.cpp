#include "render/motion_sampling.h"

#include <cmath>
#include <vector>

namespace angio {

namespace {

constexpr double kStepRatio = 1.189207115002721;  // 2^(1/4)
constexpr double kFinerHeadroom = 0.75;
constexpr double kCoarsestPerFastIsd = 4.0;

// From the finest (medium's isd) to the fast level's, both included, then on in the same ratio
// up to kCoarsestPerFastIsd times the fast level's.
std::vector<double> isdLadder(double finest, double fast) {
  std::vector<double> ladder;
  for (double isd = finest; isd < fast * (1 - 1e-9); isd *= kStepRatio) ladder.push_back(isd);
  for (double isd = fast; isd <= fast * kCoarsestPerFastIsd * (1 + 1e-9); isd *= kStepRatio)
    ladder.push_back(isd);
  return ladder;
}

}  // namespace

Sampling motionSampling(const LevelSamplings& levels, std::optional<MeasuredFrame> last,
                        double budgetMs) {
  Sampling sampling = levels[int(Quality::fast)];
  const double finest = levels[int(Quality::medium)].isd;
  if (budgetMs <= 0 || !last || !(last->ms > 0) || !(last->isd > 0)) return sampling;
  const std::vector<double> ladder = isdLadder(finest, sampling.isd);
  for (double isd : ladder) {
    const double predicted = last->ms * (last->isd / isd) * (last->isd / isd);
    const bool finer = isd < last->isd * (1 - 1e-9);
    if (predicted <= budgetMs * (finer ? kFinerHeadroom : 1.0)) {
      sampling.isd = isd;
      return sampling;
    }
  }
  sampling.isd = ladder.back();  // even the coarsest step is over budget: it is the best there is
  return sampling;
}

}  // namespace angio
