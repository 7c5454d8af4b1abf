#pragma once
// `angioray bench --profile`: where a level's samples go (core/ray_profile.h), summed over the
// bench's angles, and what one evaluated sample costs: the CPU time of the level's timed frames
// over the samples they evaluated (ns per sample per core, the per-sample cost of the inner loop
// whatever the thread count).
#include <string>
#include <vector>

#include "core/ray_profile.h"

namespace angio {

struct LevelProfile {
  std::string level;
  RayProfile total;  // over all frames
  int frames = 0;
  double nsPerEvaluatedSample = 0;  // median CPU ms per frame / evaluated samples per frame
  double templateMs = 0;            // median wall ms per frame building the ray templates
  bool operator==(const LevelProfile&) const = default;
};

std::string formatProfiles(const std::vector<LevelProfile>& profiles);

}  // namespace angio
