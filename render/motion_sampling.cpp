#include "render/motion_sampling.h"

#include <cmath>
#include <vector>

namespace angio {

namespace {

constexpr double kStepRatio = 1.189207115002721;  // 2^(1/4)
constexpr double kFinerHeadroom = 0.75;

// From the finest (medium's isd) to the coarsest (fast's), both included.
std::vector<double> isdLadder(double finest, double coarsest) {
  std::vector<double> ladder;
  for (double isd = finest; isd < coarsest * (1 - 1e-9); isd *= kStepRatio) ladder.push_back(isd);
  ladder.push_back(coarsest);
  return ladder;
}

}  // namespace

Sampling motionSampling(const LevelSamplings& levels, std::optional<MeasuredFrame> last,
                        double budgetMs) {
  Sampling sampling = levels[int(Quality::fast)];
  const double finest = levels[int(Quality::medium)].isd, coarsest = sampling.isd;
  if (budgetMs <= 0 || !last || !(last->ms > 0) || !(last->isd > 0) || !(finest < coarsest))
    return sampling;
  for (double isd : isdLadder(finest, coarsest)) {
    const double predicted = last->ms * (last->isd / isd) * (last->isd / isd);
    const bool finer = isd < last->isd * (1 - 1e-9);
    if (predicted <= budgetMs * (finer ? kFinerHeadroom : 1.0)) {
      sampling.isd = isd;
      return sampling;
    }
  }
  return sampling;  // even the fast level is over budget: it is the coarsest there is
}

}  // namespace angio
