#include "render/sidecar_render.h"

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/fast_raycaster.h"
#include "core/reference_raycaster.h"
#include "core/view_geometry.h"
#include "render/hybrid_cpr_step.h"
#include "io/input_error.h"

namespace angio {

namespace {

Image renderTables(const Volume& volume, const RegionTables& tables, const RenderSidecar& s,
                   const SidecarRenderOptions& options) {
  if (s.raycaster == "reference") return renderReference(volume, tables, s.params, options.progress);
  std::optional<SliceTiles> built;
  if (!options.tiles) built = buildSliceTiles(volume, s.params.axis);
  const SliceTiles& tiles = options.tiles ? *options.tiles : *built;
  FastRenderStats stats;
  Image image = renderFast(volume, tiles, classifyTiles(tiles, tables), tables, s.params,
                           FastRenderOptions{.cancel = options.cancel}, &stats);
  if (options.cancelled) *options.cancelled = stats.cancelled;
  return image;
}

// VesselGlyph (thesis ch. 5) of all paths; hybrid: the selected paths' CPR in their focus's
// footprint (gui/hybrid_cpr_step.h).
Image renderVesselGlyph(const Volume& volume, const Centerlines& centerlines, const RenderSidecar& s,
                        const SidecarRenderOptions& options) {
  const VesselGlyphRecipe& vg = *s.vesselGlyph;
  const ViewGeometry view = makeViewGeometry(volume, s.params);
  const RayRegions regions = buildRayRegions(volume, view, centerlines, vg.settings);
  const TfTable focus = buildTable(vg.focusTf), context = buildTable(vg.contextTf);
  const TfTable outside = buildTable(vg.outsideTf.value_or(TransferFunction{}));
  const RegionTables tables{&regions, &focus, &context, vg.outsideTf ? &outside : nullptr};
  Image image = renderTables(volume, tables, s, options);
  if (!s.hybrid || (options.cancelled && *options.cancelled)) return image;
  HybridCprStep(volume, centerlines, vg, *s.hybrid, options.warn).composite(view, regions, image);
  return image;
}

}  // namespace

Image renderSidecarImage(const Volume& volume, const Centerlines& centerlines, const RenderSidecar& s,
                         const SidecarRenderOptions& options) {
  if (s.vesselGlyph) return renderVesselGlyph(volume, centerlines, s, options);
  const TfTable table = buildTable(s.tf);
  return renderTables(volume, singleTable(table), s, options);
}

}  // namespace angio
