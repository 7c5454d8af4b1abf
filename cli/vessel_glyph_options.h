#pragma once
// The VesselGlyph (thesis ch. 5) and DVR+CPR hybrid (thesis fig. 5.4) options of `angioray
// render`, and their translation into the render's recipe (io/render_sidecar.h).
#include <optional>
#include <string>

#include "render/recipe_json.h"

namespace CLI {
class App;
}

namespace angio {

// Unset options take their defaults; each needs --centerlines (and the hybrid ones --hybrid-cpr).
struct VesselGlyphCliOptions {
  std::string centerlines;
  std::optional<std::string> focus;      // spec, default "circle:radius=2.0x"
  std::optional<std::string> context;    // spec, default "slab:front=20,back=20,width=40"
  std::optional<std::string> focusTf;    // default: --tf
  std::optional<std::string> contextTf;  // default: --tf faded (render/region_tfs.h)
  std::optional<std::string> outside;    // "clip" (default) or a TF
  bool cleft = false;
  bool halfVessel = false;
  bool hybrid = false;
  std::optional<std::string> hybridPath;  // "all" (default) or an index
  std::optional<double> transitionMm;
  std::optional<double> cprWindow, cprLevel;  // grey CPR instead of the focus TF's colors
};

// Adds --centerlines, --vg-focus, --vg-context, --focus-tf, --context-tf, --vg-outside, --cleft,
// --half-vessel, --hybrid-cpr, --hybrid-path, --transition, --cpr-window, --cpr-level.
void addVesselGlyphOptions(CLI::App& render, VesselGlyphCliOptions& options);

// Nothing without --centerlines. Loads the TFs (`baseTf` is --tf, the default for both regions).
// Throws std::invalid_argument with one line for a bad spec or an option given without what it
// needs, InputError for a TF that does not load.
std::optional<VesselGlyphRecipe> vesselGlyphRecipe(const VesselGlyphCliOptions& options,
                                                   const std::string& baseTf);
std::optional<HybridCprRecipe> hybridCprRecipe(const VesselGlyphCliOptions& options);

}  // namespace angio
