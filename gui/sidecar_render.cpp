#include "gui/sidecar_render.h"

#include <chrono>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>

#include "core/fast_raycaster.h"
#include "core/reference_raycaster.h"
#include "core/view_geometry.h"
#include "gui/progress_line.h"
#include "gui/render_job.h"
#include "io/centerline_file.h"
#include "io/image_export.h"
#include "io/input_error.h"
#include "io/volume_reader.h"
#include "vessel/cpr.h"
#include "vessel/cpr_hybrid.h"

namespace angio {

namespace fs = std::filesystem;

namespace {

void printWarning(const std::string& warning) {
  std::fprintf(stderr, "angioray: warning: %s\n", warning.c_str());
}

Image renderTables(const Volume& volume, const RegionTables& tables, const RenderSidecar& s) {
  ProgressLine progress("rendering");
  if (s.raycaster == "reference") return renderReference(volume, tables, s.params, std::ref(progress));
  const SliceTiles tiles = buildSliceTiles(volume, s.params.axis);
  return renderFast(volume, tiles, classifyTiles(tiles, tables), tables, s.params);
}

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

// The layout of the projected CPR of `paths` in the DVR's view.
CprLayout projectedCpr(const Centerlines& paths, const ViewGeometry& view) {
  CprSettings settings;
  settings.mode = CprMode::projected;
  CprLayout layout;
  try {
    layout = layoutCpr(paths.paths, view, settings);
  } catch (const CprPathError& error) {
    throw InputError(paths.source, error.what());
  }
  for (const std::string& warning : layout.warnings) printWarning(paths.source + ": " + warning);
  return layout;
}

// The CPR shown through the focus TF or a grey window.
CprDisplay hybridDisplay(const VesselGlyphRecipe& vg, const HybridCprRecipe& hybrid) {
  CprDisplay display;
  display.centerlineMarker = display.ruler = false;
  if (hybrid.grey) display.windowLevel = *hybrid.grey;
  else display.tf = vg.focusTf;
  return display;
}

// VesselGlyph (thesis ch. 5) of all paths; hybrid: the footprint of the selected paths' focus
// shows their CPR wherever the CPR samples it (the cut in image space); footprint pixels the CPR
// leaves empty (beyond a path's ends) keep the VesselGlyph DVR's focus, so the vessel never shows
// a hole, and paths not selected stay VesselGlyph DVR.
Image renderVesselGlyph(const Volume& volume, const Centerlines& centerlines, const RenderSidecar& s) {
  const VesselGlyphRecipe& vg = *s.vesselGlyph;
  const ViewGeometry view = makeViewGeometry(volume, s.params);
  const RayRegions regions = buildRayRegions(volume, view, centerlines, vg.settings);
  const TfTable focus = buildTable(vg.focusTf), context = buildTable(vg.contextTf);
  const TfTable outside = buildTable(vg.outsideTf.value_or(TransferFunction{}));
  const RegionTables tables{&regions, &focus, &context, vg.outsideTf ? &outside : nullptr};
  Image image = renderTables(volume, tables, s);
  if (!s.hybrid) return image;
  const Centerlines selected = hybridPaths(centerlines, s.hybrid->path);
  const CprLayout layout = projectedCpr(selected, view);
  const std::vector<std::uint8_t> cut =
      selected.paths.size() == centerlines.paths.size()
          ? focusFootprint(regions)
          : focusFootprint(buildRayRegions(volume, view, selected, vg.settings));
  compositeCprInPlace(image, volume, layout, cut, hybridDisplay(vg, *s.hybrid),
                      {s.hybrid->transitionMm, view.pixelMm});
  return image;
}

}  // namespace

Image renderSidecarImage(const Volume& volume, const Centerlines& centerlines, const RenderSidecar& s) {
  if (s.vesselGlyph) return renderVesselGlyph(volume, centerlines, s);
  const TfTable table = buildTable(s.tf);
  return renderTables(volume, singleTable(table), s);
}

double renderSidecarToFile(RenderSidecar sidecar, const fs::path& out) {
  sidecar.image = std::filesystem::absolute(out).lexically_normal().string();
  ReadOptions read;
  read.labelPath = sidecar.labels;
  read.warn = printWarning;
  Volume volume;
  {
    ProgressLine loading("loading " + sidecar.dataset);
    read.progress = std::ref(loading);
    volume = readVolume(sidecar.dataset, read).volume;
  }
  Centerlines centerlines;
  if (sidecar.vesselGlyph) {
    CenterlineLoadOptions load;
    load.warn = printWarning;
    centerlines = toVolumeFrame(loadCenterlines(sidecar.vesselGlyph->centerlines, load), volume);
    checkCenterlinesInside(centerlines, volume, load);
  }
  checkImageSize(makeViewGeometry(volume, sidecar.params), out);
  const auto start = std::chrono::steady_clock::now();
  const Image image = renderSidecarImage(volume, centerlines, sidecar);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  exportImage(image, out, renderSidecarMetadata(sidecar));
  saveRenderSidecar(sidecar, sidecarPathFor(out));
  std::printf("wrote %s (%dx%d, rendered in %.2f s) and %s\n", out.string().c_str(), image.width,
              image.height, seconds, sidecarPathFor(out).string().c_str());
  return seconds;
}

}  // namespace angio
