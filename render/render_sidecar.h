#pragma once
// The JSON sidecar of an exported render (issue 4 item 6): every parameter needed to render the
// image again, byte for byte (`angioray render --params IMAGE.png.json [--out OTHER]`).
//
// API for every exporter (CLI `render`, GUI exports): fill a RenderSidecar with exactly what the
// image was rendered from, export the image, then
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
//    "compositing": "dvr" | "mip", "mip": {"window", "level"}, "tf": {TF JSON},
//    "vessel_glyph": null | {"centerlines", "focus": {"radius_mode": "factor" | "mm", "radius",
//        "margin_mm"}, "context": {"shape": "none" | "slab" | "tube", "front_mm", "back_mm",
//        "half_width_mm" (number or "inf"), "tube": {focus-like}}, "cleft", "half_vessel",
//        "unknown_vessel_radius_mm", "simplify_tolerance_mm", "focus_tf": {TF}, "context_tf": {TF},
//        "outside_tf": {TF} | null (clipped)}  (the settings' keys: io/vessel_glyph_json.h, which
//        session files share),
//    "hybrid_cpr": null | {"path": "all" | "N", "transition_mm", "display": "tf" | "grey",
//        "window", "level"}}
#include <filesystem>
#include <optional>
#include <string>

#include "core/render_params.h"
#include "core/transfer_function.h"
#include "io/image_export.h"
#include "vessel/cpr_display.h"
#include "vessel/vessel_glyph.h"

namespace angio {

// VesselGlyph focus+context rendering (issue 5): regions from the centerlines, a TF per region.
struct VesselGlyphRecipe {
  std::string centerlines;  // centerline file
  VesselGlyphSettings settings;
  TransferFunction focusTf;
  TransferFunction contextTf;
  std::optional<TransferFunction> outsideTf;  // none: the outside is clipped

  friend bool operator==(const VesselGlyphRecipe&, const VesselGlyphRecipe&) = default;
};

// DVR+CPR hybrid (issue 6 item 5, thesis fig. 5.4/5.5): the focus footprint shows the projected CPR.
struct HybridCprRecipe {
  std::string path = "all";           // "all" or a path index (vessel/cpr_layout.h selectPaths)
  double transitionMm = 0;            // width of the smooth band around the cut; 0 = hard edge
  std::optional<WindowLevel> grey;    // none: the CPR coloured through the focus TF

  friend bool operator==(const HybridCprRecipe&, const HybridCprRecipe&) = default;
};

struct RenderSidecar {
  std::string image;    // the image it describes (--params without --out renders to it again)
  std::string dataset;  // volume file or DICOM folder
  std::string labels;   // label volume, "" = none
  std::optional<Quality> quality;  // the level the sampling started from (metadata only)
  std::string raycaster = "fast";  // "fast" | "reference" (the same image; kept for the record)
  RenderParams params;
  TransferFunction tf;  // plain DVR (and MIP's window/level source); unused with vesselGlyph
  std::optional<VesselGlyphRecipe> vesselGlyph;
  std::optional<HybridCprRecipe> hybrid;  // needs vesselGlyph

  friend bool operator==(const RenderSidecar&, const RenderSidecar&) = default;
};

// IMAGE + ".json", e.g. "aorta.png" -> "aorta.png.json".
std::filesystem::path sidecarPathFor(const std::filesystem::path& image);

// Atomic (temp name, then rename). Throws InputError if it cannot be written.
void saveRenderSidecar(const RenderSidecar& sidecar, const std::filesystem::path& file);
std::string renderSidecarJson(const RenderSidecar& sidecar);

// Throws InputError(file, one-line problem) for a missing or unreadable file, bad JSON, a missing
// or mistyped key, an unknown enum value or a bad TF.
RenderSidecar loadRenderSidecar(const std::filesystem::path& file);
RenderSidecar parseRenderSidecar(const std::string& json, const std::filesystem::path& source);

// renderMetadata of the sidecar's parameters plus VesselGlyph and hybrid settings.
ImageMetadata renderSidecarMetadata(const RenderSidecar& sidecar);

}  // namespace angio
