#pragma once
// The VesselGlyph region settings as JSON: the one form render sidecars (io/render_sidecar.h,
// "vessel_glyph") and session files (gui/session_file.h, "vessel_glyph") share, sizes in mm:
//   {"focus": {"radius_mode": "factor" | "mm", "radius", "margin_mm"},
//    "context": {"shape": "none" | "slab" | "tube", "front_mm", "back_mm",
//                "half_width_mm" (number or "inf"), "tube": {focus-like}},
//    "cleft", "half_vessel", "unknown_vessel_radius_mm", "simplify_tolerance_mm"}
// Each reader checks these keys in its own file's way (a sidecar needs every key, a session keeps
// defaults for missing ones); the names of the enum values are here for both.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "vessel/vessel_glyph.h"

namespace angio {

// The keys above, in that order.
nlohmann::ordered_json vesselGlyphSettingsJson(const VesselGlyphSettings& settings);

// "factor" | "mm" and "none" | "slab" | "tube", as written above.
const char* radiusModeName(RadiusMode mode);
std::optional<RadiusMode> parseRadiusMode(const std::string& name);
const char* contextShapeName(ContextShape shape);
std::optional<ContextShape> parseContextShape(const std::string& name);

}  // namespace angio
