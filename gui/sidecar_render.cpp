#include "gui/sidecar_render.h"

#include <chrono>
#include <cstdio>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/fast_raycaster.h"
#include "core/reference_raycaster.h"
#include "core/view_geometry.h"
#include "gui/hybrid_cpr_step.h"
#include "gui/progress_line.h"
#include "gui/render_job.h"
#include "io/centerline_file.h"
#include "io/image_export.h"
#include "io/input_error.h"
#include "io/volume_reader.h"

namespace angio {

namespace fs = std::filesystem;

namespace {

void printWarning(const std::string& warning) {
  std::fprintf(stderr, "angioray: warning: %s\n", warning.c_str());
}

Image renderTables(const Volume& volume, const RegionTables& tables, const RenderSidecar& s,
                   const SidecarRenderOptions& options) {
  if (s.raycaster == "reference") {
    ProgressLine progress("rendering");
    return renderReference(volume, tables, s.params, std::ref(progress));
  }
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
  HybridCprStep(volume, centerlines, vg, *s.hybrid, printWarning).composite(view, regions, image);
  return image;
}

}  // namespace

Image renderSidecarImage(const Volume& volume, const Centerlines& centerlines, const RenderSidecar& s,
                         const SidecarRenderOptions& options) {
  if (s.vesselGlyph) return renderVesselGlyph(volume, centerlines, s, options);
  const TfTable table = buildTable(s.tf);
  return renderTables(volume, singleTable(table), s, options);
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
