#pragma once
// The Vessels section in a session file: "vessels": {"file", "unsaved", "paths": [{"name",
// "control_points_mm": [[x, y, z], ...], "points": [[x, y, z, radius_mm], ...]}]}, physical mm
// (LPS), inline so a session keeps traced paths that were never saved to a file. Numbers are
// written so they read back as the same doubles. On restore the app uses the inline paths when
// they were unsaved, else reads their file again (gui/app_vessel.cpp).
#include <filesystem>

#include <nlohmann/json.hpp>

#include "gui/document.h"

namespace angio {

nlohmann::json vesselsJson(const VesselsState& vessels);
// Throws InputError(source, "vessels.paths[2].points: ...") for anything malformed.
VesselsState parseVessels(const nlohmann::json& json, const std::filesystem::path& source);

}  // namespace angio
