// `angioray render`: volume + TF + view (+ VesselGlyph, hybrid) -> image file and its sidecar.
#include <filesystem>
#include <stdexcept>

#include "gui/commands.h"
#include "gui/sidecar_render.h"
#include "io/render_sidecar.h"
#include "io/tf_file.h"

namespace angio {

namespace {

RenderParams paramsFrom(const RenderOptions& o, const TransferFunction& tf) {
  RenderParams p;
  p.axis = *parseAxis(o.axis);
  p.angleDeg = o.angleDeg;
  p.sampling = qualitySampling(*parseQuality(o.quality));
  if (o.isd) p.sampling.isd = *o.isd;
  if (o.osd) p.sampling.osd = *o.osd;
  if (o.ert) p.sampling.ert = *o.ert;
  if (o.filter) p.sampling.filter = *parseFilter(*o.filter);
  if (o.shading) p.shading.enabled = *o.shading == "on";
  if (o.ka) p.shading.ka = *o.ka;
  if (o.kd) p.shading.kd = *o.kd;
  if (o.mip) p.compositing = Compositing::mip;
  p.mip.window = o.window.value_or(tf.mipWindow);
  p.mip.level = o.level.value_or(tf.mipLevel);
  return p;
}

// Paths as absolute ones, so the sidecar works from any directory.
std::string absolutePath(const std::string& path) {
  return path.empty() ? path : std::filesystem::absolute(path).lexically_normal().string();
}

RenderSidecar sidecarFrom(const RenderOptions& o) {
  if (o.volume.empty() || o.out.empty())
    throw std::invalid_argument("render needs VOLUME and --out (or --params SIDECAR.json)");
  RenderSidecar s;
  s.vesselGlyph = vesselGlyphRecipe(o.vesselGlyph, o.tf);
  s.hybrid = hybridCprRecipe(o.vesselGlyph);
  if (s.vesselGlyph && o.mip) throw std::invalid_argument("--mip cannot be combined with --centerlines");
  s.dataset = absolutePath(o.volume);
  s.labels = absolutePath(o.labels);
  s.quality = parseQuality(o.quality);
  s.raycaster = o.reference ? "reference" : "fast";
  s.tf = loadPresetOrFile(o.tf);
  s.params = paramsFrom(o, s.tf);
  return s;
}

}  // namespace

int runRender(const RenderOptions& options) {
  if (options.params.empty()) {
    renderSidecarToFile(sidecarFrom(options), options.out);
    return 0;
  }
  const RenderSidecar sidecar = loadRenderSidecar(options.params);
  renderSidecarToFile(sidecar, options.out.empty() ? sidecar.image : options.out);
  return 0;
}

}  // namespace angio
