#pragma once
// The DVR+CPR hybrid's step after the VesselGlyph DVR of one view (thesis sec. 5.2.2, fig. 5.4
// and 5.5): the projected CPR of the selected paths, laid out in the DVR's own view (so the two
// register pixel for pixel), composited into the selected paths' focus footprint
// (vessel/cpr_hybrid.h). A prepared scene with a hybrid runs it after every render of a view
// (render/prepared_scene.h), so the window's levels, exports and `render --params` agree.
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "core/image.h"
#include "core/region_intervals.h"
#include "core/view_geometry.h"
#include "core/volume.h"
#include "render/recipe_json.h"
#include "vessel/centerline.h"
#include "vessel/cpr_display.h"
#include "vessel/vessel_glyph.h"

namespace angio {

// Grey through the recipe's window, else the focus TF's colors; no marker line, no ruler.
CprDisplay hybridCprDisplay(const VesselGlyphRecipe& vesselGlyph, const HybridCprRecipe& hybrid);

class HybridCprStep {
 public:
  using Warn = std::function<void(const std::string&)>;
  // `volume` must outlive the step; `centerlines` are in its volume frame (all the VesselGlyph
  // paths). Throws InputError naming centerlines.source for a path selection that names no path.
  HybridCprStep(const Volume& volume, const Centerlines& centerlines,
                const VesselGlyphRecipe& vesselGlyph, const HybridCprRecipe& hybrid, Warn warn = {});

  // `dvr`: the VesselGlyph DVR of `view`, rendered with `regions` (those of all paths). Safe to
  // call from one thread at a time or several (they take turns). Throws InputError as layoutCpr
  // does for a path the view cannot lay out.
  void composite(const ViewGeometry& view, const RayRegions& regions, Image& dvr);

 private:
  const Volume& volume_;
  Centerlines selected_;
  bool allPaths_ = true;
  std::unique_ptr<RayRegionBuilder> selectedRegions_;  // set when only some paths are selected
  RayRegions scratch_;                                 // their regions (buffers reused)
  CprDisplay display_;
  double transitionMm_ = 0;
  Warn warn_;
  std::mutex mutex_;
};

}  // namespace angio
