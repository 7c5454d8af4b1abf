#pragma once
// A render recipe: everything that decides an image, as plain data (the dataset and labels by
// name, the view, sampling, shading, compositing, the TFs in full, VesselGlyph focus+context and
// the DVR+CPR hybrid). The window, `angioray render`, exports, rotation series and bench all
// render recipes through render/prepared_scene.h, so the same recipe gives the same pixels
// whoever asks. Its JSON is the sidecar written beside every exported image
// (render/recipe_json.h).
#include <optional>
#include <string>

#include "core/render_params.h"
#include "core/transfer_function.h"
#include "vessel/cpr_display.h"
#include "vessel/vessel_glyph.h"

namespace angio {

// The reference raycaster gives the fast one's image (up to float rounding); it is kept to check
// the fast one and for the record.
enum class Raycaster { fast, reference };

// VesselGlyph focus+context rendering (thesis ch. 5): regions from the centerlines, a TF per
// region.
struct VesselGlyphRecipe {
  std::string centerlines;  // centerline file
  VesselGlyphSettings settings;
  TransferFunction focusTf;
  TransferFunction contextTf;
  std::optional<TransferFunction> outsideTf;  // none: the outside is clipped

  friend bool operator==(const VesselGlyphRecipe&, const VesselGlyphRecipe&) = default;
};

// DVR+CPR hybrid (thesis sec. 5.2.2, fig. 5.4/5.5): the focus footprint shows the projected CPR.
struct HybridCprRecipe {
  std::string path = "all";         // "all" or a path index (vessel/cpr_layout.h selectPaths)
  double transitionMm = 0;          // width of the smooth band around the cut; 0 = hard edge
  std::optional<WindowLevel> grey;  // none: the CPR colored through the focus TF

  friend bool operator==(const HybridCprRecipe&, const HybridCprRecipe&) = default;
};

struct RenderRecipe {
  std::string image;    // the image it describes (a sidecar's; --params without --out renders to it)
  std::string dataset;  // volume file or DICOM folder
  std::string labels;   // label volume, "" = none
  std::optional<Quality> quality;  // the level the sampling started from (metadata only)
  Raycaster raycaster = Raycaster::fast;
  RenderParams params;
  TransferFunction tf;  // plain DVR (and MIP's window/level source); unused with vesselGlyph
  std::optional<VesselGlyphRecipe> vesselGlyph;
  std::optional<HybridCprRecipe> hybrid;  // needs vesselGlyph

  friend bool operator==(const RenderRecipe&, const RenderRecipe&) = default;
};

}  // namespace angio
