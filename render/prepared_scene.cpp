#include "render/prepared_scene.h"

namespace angio {

std::shared_ptr<const PreparedScene> PreparedScene::prepare(const Volume& volume,
                                                            const Centerlines& centerlines,
                                                            const RenderRecipe& recipe,
                                                            const PreparedScene* previous, Warn warn) {
  std::shared_ptr<PreparedScene> scene(new PreparedScene(volume, recipe));
  scene->labels_ = LabelTables(recipe.tf.labels);
  if (recipe.vesselGlyph) scene->prepareVesselGlyph(centerlines, previous, std::move(warn));
  else scene->table_ = buildTable(recipe.tf);
  return scene;
}

void PreparedScene::prepareVesselGlyph(const Centerlines& centerlines, const PreparedScene* previous,
                                       Warn warn) {
  const VesselGlyphRecipe& vg = *recipe_.vesselGlyph;
  focus_ = buildTable(vg.focusTf);
  context_ = buildTable(vg.contextTf);
  if (vg.outsideTf) outside_ = buildTable(*vg.outsideTf);

  const auto& lent = previous ? previous->regions_ : nullptr;
  if (lent && lent->builder.settings() == vg.settings && lent->centerlines == centerlines)
    regions_ = lent;
  else regions_ = std::make_shared<GuardedRegions>(centerlines, vg.settings);

  if (!recipe_.hybrid) return;
  const auto& hybrid = previous ? previous->hybrid_ : nullptr;
  if (hybrid && hybrid->vesselGlyph == vg && hybrid->hybrid == *recipe_.hybrid &&
      hybrid->centerlines == centerlines) {
    hybrid_ = hybrid;
    return;
  }
  hybrid_ = std::shared_ptr<Hybrid>(
      new Hybrid{centerlines, vg, *recipe_.hybrid,
                 HybridCprStep(volume_, centerlines, vg, *recipe_.hybrid, std::move(warn))});
}

RegionTables PreparedScene::tables(const RayRegions* regions) const {
  if (!regions_) return {nullptr, nullptr, nullptr, &table_, &labels_};
  return {regions, &focus_, &context_, recipe_.vesselGlyph->outsideTf ? &outside_ : nullptr, &labels_};
}

void PreparedScene::buildRegions(const ViewGeometry& view, RayRegions& out) const {
  if (!regions_) return;
  std::lock_guard lock(regions_->mutex);
  regions_->builder.build(view, out);
}

void PreparedScene::finish(const ViewGeometry& view, const RayRegions& regions, Image& image) const {
  if (hybrid_) hybrid_->step.composite(view, regions, image);
}

}  // namespace angio
