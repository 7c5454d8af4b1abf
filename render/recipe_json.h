#pragma once
// The JSON of a render recipe (render/render_recipe.h): the sidecar written beside every exported
// image, with every parameter needed to render the image again, byte for byte
// (`angioray render --params IMAGE.png.json [--out OTHER]`).
//
// API for every exporter (CLI `render`, GUI exports): the recipe the image was rendered from,
// export the image, then
//     saveRenderSidecar(sidecar, sidecarPathFor(imagePath));
// The TFs are stored as their full JSON content (io/tf_file.h), not by name, and numbers with
// round-trip precision, so loadRenderSidecar gives back the same values. Paths (dataset, labels,
// centerlines) are stored as given: pass absolute paths so the sidecar works from any directory.
// renderSidecarMetadata gives the image metadata that goes with a sidecar (render_metadata.h plus
// the VesselGlyph and hybrid settings).
//
// File layout (version 1):
//   {"angioray_render_sidecar": 1, "angioray_version": "...", "image": "...", "dataset": "...",
//    "labels": "", "quality": "high" | null, "raycaster": "fast" | "reference",
//    "view": {"axis": "k", "angle_deg": 30},
//    "sampling": {"isd", "osd", "filter", "ert"}, "shading": {"enabled", "ka", "kd"},
//    "compositing": "dvr" | "mip", "mip": {"window", "level"},
//    "clipping": {"crop": null | {"min_mm": [i, j, k], "max_mm": [i, j, k]},
//        "plane": null | {"facing_viewer": false, "point_mm": [i, j, k], "normal": [i, j, k]}
//                      | {"facing_viewer": true, "offset_mm"},
//        "slab": null | {"offset_mm", "thickness_mm"}}  (mm of the volume frame,
//        core/view_clipping.h; absent = nothing clipped),
//    "tf": {TF JSON},
//    "vessel_glyph": null | {"centerlines", "focus": {"radius_mode": "factor" | "mm", "radius",
//        "margin_mm"}, "context": {"shape": "none" | "slab" | "tube", "front_mm", "back_mm",
//        "half_width_mm" (number or "inf"), "tube": {focus-like}}, "cleft", "half_vessel",
//        "unknown_vessel_radius_mm", "simplify_tolerance_mm", "focus_tf": {TF}, "context_tf": {TF},
//        "outside_tf": {TF} | null (clipped)}  (the settings' keys: io/vessel_glyph_json.h, which
//        session files share),
//    "hybrid_cpr": null | {"path": "all" | "N", "transition_mm", "display": "tf" | "grey",
//        "window", "level"}}
#include <filesystem>
#include <string>

#include "io/image_export.h"
#include "render/render_recipe.h"

namespace angio {

// IMAGE + ".json", e.g. "aorta.png" -> "aorta.png.json".
std::filesystem::path sidecarPathFor(const std::filesystem::path& image);

// Atomic (temp name, then rename). Throws InputError if it cannot be written.
void saveRenderSidecar(const RenderRecipe& sidecar, const std::filesystem::path& file);
std::string renderSidecarJson(const RenderRecipe& sidecar);

// Throws InputError(file, one-line problem) for a missing or unreadable file, bad JSON, a missing
// or mistyped key, an unknown enum value or a bad TF.
RenderRecipe loadRenderSidecar(const std::filesystem::path& file);
RenderRecipe parseRenderSidecar(const std::string& json, const std::filesystem::path& source);

// The recipe as image metadata (key/value, `angioray:` attributes and a description in the
// file): how the image was made, in words.
ImageMetadata renderSidecarMetadata(const RenderRecipe& recipe);

}  // namespace angio
