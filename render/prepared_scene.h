#pragma once
// A render recipe made ready to render: the TF tables of its regions, the VesselGlyph region
// builder (the view-independent tubes, thesis sec. 5.1) and the DVR+CPR hybrid step, built once
// from the recipe, the volume and the centerlines and never changed afterwards. Every render of
// it - each level of the progressive renderer, each view of a rotation series, each bench frame -
// shares them; what depends on the view (the rays' regions, the image) is made per render by
// render/frame_renderer.h. As in pbrt-v4's RenderCPU, the plain-data description is the only
// input: callers never assemble tables, regions or hybrid steps themselves.
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "core/compositing.h"
#include "core/image.h"
#include "core/label_tables.h"
#include "core/region_intervals.h"
#include "core/transfer_function.h"
#include "core/view_geometry.h"
#include "core/volume.h"
#include "render/hybrid_cpr_step.h"
#include "render/render_recipe.h"
#include "vessel/centerline.h"
#include "vessel/vessel_glyph.h"

namespace angio {

class PreparedScene {
 public:
  using Warn = std::function<void(const std::string&)>;

  // `volume` must outlive the scene. `centerlines` (volume frame) are used iff recipe.vesselGlyph
  // is set. `previous` (optional, e.g. the scene a TF edit replaces) lends its region builder and
  // hybrid step where the centerlines and the settings they were made from are the same, so a TF
  // edit does not rebuild the tubes. Throws InputError for a hybrid path selection that names no
  // path, and what RayRegionBuilder throws for unusable settings.
  static std::shared_ptr<const PreparedScene> prepare(const Volume& volume,
                                                      const Centerlines& centerlines,
                                                      const RenderRecipe& recipe,
                                                      const PreparedScene* previous = nullptr,
                                                      Warn warn = {});

  const Volume& volume() const { return volume_; }
  const RenderRecipe& recipe() const { return recipe_; }
  bool hasRegions() const { return regions_ != nullptr; }

  // The TF of each region for rays with `regions` (VesselGlyph), or the recipe's TF alone.
  RegionTables tables(const RayRegions* regions) const;
  // The rays' regions in `view` (VesselGlyph only). Callers on several threads take turns.
  void buildRegions(const ViewGeometry& view, RayRegions& out) const;
  // After the VesselGlyph image of `view` (rendered with `regions`): the hybrid's projected CPR
  // composited into the focus footprint; nothing without a hybrid. Throws as HybridCprStep does.
  void finish(const ViewGeometry& view, const RayRegions& regions, Image& image) const;

 private:
  // RayRegionBuilder is not re-entrant: renders on several threads take turns.
  struct GuardedRegions {
    GuardedRegions(const Centerlines& inVolumeFrame, const VesselGlyphSettings& settings)
        : centerlines(inVolumeFrame), builder(inVolumeFrame, settings) {}
    Centerlines centerlines;  // what the builder was made from
    std::mutex mutex;
    RayRegionBuilder builder;
  };
  struct Hybrid {
    Centerlines centerlines;  // what the step was made from, with the recipes below
    VesselGlyphRecipe vesselGlyph;
    HybridCprRecipe hybrid;
    HybridCprStep step;
  };

  PreparedScene(const Volume& volume, const RenderRecipe& recipe) : volume_(volume), recipe_(recipe) {}
  void prepareVesselGlyph(const Centerlines& centerlines, const PreparedScene* previous, Warn warn);

  const Volume& volume_;
  RenderRecipe recipe_;
  TfTable table_{}, focus_{}, context_{}, outside_{};
  LabelTables labels_;  // from the main TF's label styles, in every region
  std::shared_ptr<GuardedRegions> regions_;
  std::shared_ptr<Hybrid> hybrid_;
};

}  // namespace angio
