#include "render/hybrid_cpr_step.h"

#include "io/input_error.h"
#include "vessel/cpr_hybrid.h"
#include "vessel/cpr_layout.h"

namespace angio {

namespace {

// The centerlines a hybrid shows: the selected paths only (their footprint is the cut).
Centerlines hybridPaths(const Centerlines& centerlines, const std::string& which) {
  Centerlines selected = centerlines;
  try {
    selected.paths = selectPaths(centerlines, which);
  } catch (const CprPathError& error) {
    throw InputError(centerlines.source, error.what());
  }
  return selected;
}

}  // namespace

CprDisplay hybridCprDisplay(const VesselGlyphRecipe& vesselGlyph, const HybridCprRecipe& hybrid) {
  CprDisplay display;
  display.centerlineMarker = display.ruler = false;
  if (hybrid.grey) display.windowLevel = *hybrid.grey;
  else display.tf = vesselGlyph.focusTf;
  return display;
}

HybridCprStep::HybridCprStep(const Volume& volume, const Centerlines& centerlines,
                             const VesselGlyphRecipe& vesselGlyph, const HybridCprRecipe& hybrid,
                             Warn warn)
    : volume_(volume), selected_(hybridPaths(centerlines, hybrid.path)),
      allPaths_(selected_.paths.size() == centerlines.paths.size()),
      display_(hybridCprDisplay(vesselGlyph, hybrid)), transitionMm_(hybrid.transitionMm),
      warn_(std::move(warn)) {
  if (!allPaths_) selectedRegions_ = std::make_unique<RayRegionBuilder>(selected_, vesselGlyph.settings);
}

// Footprint pixels the CPR leaves empty (beyond a path's ends) keep the VesselGlyph DVR's focus,
// so the vessel never shows a hole; paths not selected stay VesselGlyph DVR.
void HybridCprStep::composite(const ViewGeometry& view, const RayRegions& regions, Image& dvr) {
  std::lock_guard lock(mutex_);
  CprSettings settings;
  settings.mode = CprMode::projected;
  CprLayout layout;
  try {
    layout = layoutCpr(selected_.paths, view, settings);
  } catch (const CprPathError& error) {
    throw InputError(selected_.source, error.what());
  }
  if (warn_)
    for (const std::string& warning : layout.warnings) warn_(selected_.source + ": " + warning);
  if (selectedRegions_) selectedRegions_->build(view, scratch_);
  const std::vector<std::uint8_t> cut = focusFootprint(selectedRegions_ ? scratch_ : regions);
  compositeCprInPlace(dvr, volume_, layout, cut, display_, {transitionMm_, view.pixelMm});
}

}  // namespace angio
