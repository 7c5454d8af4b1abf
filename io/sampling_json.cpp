#include "io/sampling_json.h"

namespace angio {

nlohmann::ordered_json samplingJson(const Sampling& sampling) {
  using Json = nlohmann::ordered_json;
  const auto& adaptive = sampling.adaptive;
  return {{"isd", sampling.isd},
          {"osd", sampling.osd},
          {"filter", toString(sampling.filter)},
          {"ert", sampling.ert},
          {"preintegrated", sampling.preintegrated},
          {"adaptive", adaptive ? Json{{"tolerance", adaptive->tolerance},
                                       {"initial_step", adaptive->initialStep},
                                       {"min_step", adaptive->minStep}}
                                : Json(nullptr)},
          {"adaptive_sampling", sampling.adaptiveSampling
                                    ? Json{{"levels", sampling.adaptiveSampling->levels},
                                           {"ray_levels", sampling.adaptiveSampling->rayLevels},
                                           {"tolerance", sampling.adaptiveSampling->tolerance}}
                                    : Json(nullptr)}};
}

}  // namespace angio
