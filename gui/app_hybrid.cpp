// The DVR+CPR hybrid in App (thesis sec. 5.2.2, fig. 5.4 and 5.5; its controls are the CPR
// section's, gui/panel_cpr.h): the finish step the progressive renderer runs on every level's
// VesselGlyph image (core/progressive_renderer.h RegionSource::finish): the projected CPR
// composited into the focus footprint in the level's own view, so each level shows the hybrid,
// aligned to the pixel, and the UI thread only uploads it.
#include <cstdio>
#include <exception>
#include <memory>

#include "gui/app.h"
#include "render/hybrid_cpr_step.h"

namespace angio {

namespace {

constexpr const char* kColouringNames[] = {"cta-lumen", "calcium", "focus-tf"};

}  // namespace

// Null when the hybrid is off or cannot be made (the problem is shown in the CPR section).
std::function<void(const ViewGeometry&, const RayRegions&, Image&)> App::hybridFinishStep() {
  vessel_.hybridProblem.clear();
  const std::optional<HybridCprRecipe> hybrid = hybridRecipe();
  const std::optional<VesselGlyphRecipe> vesselGlyph = vesselGlyphRecipe();
  if (!hybrid || !vesselGlyph) return {};
  try {
    auto step = std::make_shared<HybridCprStep>(data_.volume, *framedCenterlines(), *vesselGlyph, *hybrid);
    return [step](const ViewGeometry& view, const RayRegions& regions, Image& image) {
      step->composite(view, regions, image);
    };
  } catch (const std::exception& error) {
    vessel_.hybridProblem = error.what();
    return {};
  }
}

nlohmann::json App::hybridReport() const {
  const CprState& cpr = doc().cpr;
  return {{"enabled", cpr.hybrid},
          {"rendering", vessel_.source && vessel_.source->finish},
          {"path", cpr.path},
          {"transition_mm", cpr.transitionMm},
          {"colouring", kColouringNames[int(cpr.colouring)]},
          {"problem", vessel_.hybridProblem}};
}

}  // namespace angio
