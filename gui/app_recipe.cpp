// What App shows, as the render recipe of io/render_sidecar.h: exports (one image, rotation
// series) render it with gui/sidecar_render.h, as `angioray render --params` of their sidecars
// does, so an export is the window's image at the export's sampling.
#include <filesystem>

#include "gui/app.h"
#include "gui/app_export.h"
#include "vessel/cpr_display.h"

namespace angio {

std::optional<VesselGlyphRecipe> App::vesselGlyphRecipe() const {
  const VesselGlyphPanel& vg = vessel_;
  if (!vg.physical) return std::nullopt;
  VesselGlyphRecipe recipe;
  std::error_code error;
  recipe.centerlines = std::filesystem::absolute(vg.file, error).lexically_normal().string();
  recipe.settings = doc().vesselGlyph.settings;
  recipe.focusTf = doc().vesselGlyph.focusTf;
  recipe.contextTf = doc().vesselGlyph.contextTf;
  if (doc().vesselGlyph.outsideRendered) recipe.outsideTf = doc().tf;  // what vesselRegions renders it with
  return recipe;
}

std::optional<HybridCprRecipe> App::hybridRecipe() const {
  const CprState& cpr = doc().cpr;
  if (!cpr.hybrid) return std::nullopt;
  HybridCprRecipe recipe;
  recipe.path = cpr.path < 0 ? "all" : std::to_string(cpr.path);
  recipe.transitionMm = cpr.transitionMm;
  if (cpr.colouring == CprColouring::ctaLumen) recipe.grey = kCtaLumenWindow;
  if (cpr.colouring == CprColouring::calcium) recipe.grey = kCalciumWindow;
  return recipe;
}

RenderSidecar App::exportRecipe() const {
  RenderSidecar recipe = exportSidecar(doc(), data_.name, export_.ui.isd);
  if (!vessel_.source) return recipe;  // plain DVR/MIP on screen
  recipe.vesselGlyph = vesselGlyphRecipe();
  if (vessel_.source->finish) recipe.hybrid = hybridRecipe();
  return recipe;
}

Centerlines App::exportCenterlines() {
  if (!vessel_.source) return {};
  const Centerlines* framed = framedCenterlines();  // mapped already: the source was made from them
  return framed ? *framed : Centerlines{};
}

}  // namespace angio
