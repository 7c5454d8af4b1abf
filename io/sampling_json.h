#pragma once
// A quality level's sampling as JSON: the one form render sidecars ("sampling") and session files
// ("levels": one per level) share:
//   {"isd", "osd", "filter": "nearest" | "trilinear" | "mean", "ert", "preintegrated",
//    "adaptive": null | {"tolerance", "initial_step", "min_step"}}
// Each reader checks these keys in its own file's way (a sidecar needs the first four and takes the
// last two as off when absent, a session keeps defaults for missing ones).
#include <nlohmann/json.hpp>

#include "core/render_params.h"

namespace angio {

// The keys above, in that order.
nlohmann::ordered_json samplingJson(const Sampling& sampling);

}  // namespace angio
