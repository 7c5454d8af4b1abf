// What App shows, as a render recipe (render/render_recipe.h), and the prepared scene the window
// renders from it. Exports (one image, rotation series) render the same recipe at the export's
// sampling, as `angioray render --params` of their sidecars does, so the window shows what an
// export gives by construction: one recipe, one path to pixels (render/frame_renderer.h).
#include <exception>
#include <filesystem>

#include "gui/app.h"
#include "gui/app_export.h"
#include "vessel/cpr_display.h"

namespace angio {

std::optional<VesselGlyphRecipe> App::vesselGlyphRecipe(const TransferFunction& main) const {
  const VesselGlyphPanel& vg = vessel_;
  if (!vg.physical) return std::nullopt;
  VesselGlyphRecipe recipe;
  std::error_code error;
  recipe.centerlines = std::filesystem::absolute(vg.file, error).lexically_normal().string();
  recipe.settings = doc().vesselGlyph.settings;
  recipe.focusTf = regionTf(doc().vesselGlyph, TfTarget::focus, main);
  recipe.contextTf = regionTf(doc().vesselGlyph, TfTarget::context, main);
  if (doc().vesselGlyph.outsideRendered) recipe.outsideTf = doc().tf;
  return recipe;
}

std::optional<HybridCprRecipe> App::hybridRecipe() const {
  const CprState& cpr = doc().cpr;
  if (!cpr.hybrid) return std::nullopt;
  HybridCprRecipe recipe;
  recipe.path = cpr.path < 0 ? "all" : std::to_string(cpr.path);
  recipe.transitionMm = cpr.transitionMm;
  if (cpr.coloring != CprColoring::focusTf) recipe.grey = cpr.window;
  return recipe;
}

// The view is left at its default: each request brings its own, so rotating keeps the scene.
std::shared_ptr<const PreparedScene> App::currentScene() {
  RenderRecipe recipe;
  recipe.dataset = absoluteDataset(data_.name);
  recipe.tf = renderedTf(doc());
  const Centerlines* centerlines = nullptr;
  if (doc().vesselGlyph.enabled && vessel_.physical) {
    try {
      centerlines = framedCenterlines();
    } catch (const std::exception& error) {
      vessel_.problem = error.what();
    }
  }
  if (centerlines) {
    recipe.vesselGlyph = vesselGlyphRecipe(recipe.tf);
    recipe.hybrid = hybridRecipe();
  }
  const Centerlines none;
  const Centerlines& used = centerlines ? *centerlines : none;
  if (scene_ && recipe == sceneRecipe_ && used == sceneCenterlines_) return scene_;
  sceneRecipe_ = recipe;
  sceneCenterlines_ = used;
  if (centerlines) vessel_.problem.clear();
  vessel_.hybridProblem.clear();
  scene_ = prepareScene(std::move(recipe), used);
  return scene_;
}

// A hybrid that cannot be made (e.g. its path is not there) leaves VesselGlyph without it, and
// VesselGlyph settings that cannot be used leave plain DVR; the panels show why.
std::shared_ptr<const PreparedScene> App::prepareScene(RenderRecipe recipe,
                                                       const Centerlines& centerlines) {
  try {
    return PreparedScene::prepare(data_.volume, centerlines, recipe, scene_.get());
  } catch (const std::exception& error) {
    if (recipe.hybrid) {
      recipe.hybrid.reset();
      std::shared_ptr<const PreparedScene> withoutHybrid = prepareScene(recipe, centerlines);
      if (withoutHybrid->hasRegions()) vessel_.hybridProblem = error.what();
      return withoutHybrid;
    }
    if (!recipe.vesselGlyph) throw;
    vessel_.problem = error.what();
    recipe.vesselGlyph.reset();
    return PreparedScene::prepare(data_.volume, centerlines, recipe, scene_.get());
  }
}

// The clipping is in the volume's millimetres, so it is made here, where the volume is known.
RenderParams App::viewParams() const {
  RenderParams params = renderParamsOf(doc());
  params.clipping = viewClippingOf(doc().clip, domainExtent(data_.volume));
  return params;
}

RenderRecipe App::exportRecipe() const {
  // What the window shows: a zoomed view's visible part, at the export's isd over the zoom.
  RenderRecipe recipe =
      exportSidecar(doc(), data_.name, export_.ui.isd / std::max(doc().view.zoom, 1.0));
  const RenderParams view = zoomedViewParams();
  recipe.params.clipping = view.clipping;
  recipe.params.window = view.window;
  recipe.labels = exportLabelFile();
  if (!scene_) return recipe;  // nothing rendered yet: plain DVR/MIP
  recipe.vesselGlyph = scene_->recipe().vesselGlyph;
  recipe.hybrid = scene_->recipe().hybrid;
  return recipe;
}

Centerlines App::exportCenterlines() {
  if (!scene_ || !scene_->hasRegions()) return {};
  const Centerlines* framed = framedCenterlines();  // mapped already: the scene was made from them
  return framed ? *framed : Centerlines{};
}

}  // namespace angio
