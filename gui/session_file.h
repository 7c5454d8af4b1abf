#pragma once
// Session files: the workstation's document (gui/document.h) as JSON, so the user comes back to
// where they left off. The VesselGlyph section is "vessel_glyph": {"centerlines",
// "centerlines_absolute", "enabled", "overlay", the settings in io/vessel_glyph_json.h's form,
// "outside": "clip" | "main-tf", "focus_tf", "context_tf" (TF JSON or null), "focus_preset",
// "context_preset"}; the Vessels section's paths are "vessels" (gui/session_vessels.h); the Crop &
// clip section is "clip": {"crop_on", "crop_min_mm": [i, j, k], "crop_max_mm", "plane_on",
// "facing_viewer", "normal_axis": "i" | "j" | "k", "flip_normal", "plane_offset_mm", "slab_on",
// "slab_offset_mm", "slab_thickness_mm"} (gui/clip_state.h). Written atomically; every problem reading one is an
// InputError, one line naming the file and the key.
// The window app writes the last session to lastSessionPath() when it quits.
#include <filesystem>
#include <string>

#include "gui/document.h"

namespace angio {

std::string toJson(const Document& session);
Document parseSession(const std::string& json, const std::filesystem::path& source);
Document loadSession(const std::filesystem::path& path);
void saveSession(const Document& session, const std::filesystem::path& path);  // atomic

// $XDG_CONFIG_HOME/angioray, else $HOME/.config/angioray (created by saveSession as needed).
std::filesystem::path configDirectory();
// configDirectory() / "last-session.json".
std::filesystem::path lastSessionPath();

}  // namespace angio
