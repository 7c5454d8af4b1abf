// `angioray render`: volume + TF + view (+ VesselGlyph, hybrid) -> image file and its sidecar.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <stdexcept>

#include "cli/load_volume.h"
#include "cli/number_list.h"
#include "cli/commands.h"
#include "cli/progress_line.h"
#include "io/atomic_write.h"
#include "io/centerline_file.h"
#include "io/input_error.h"
#include "io/tf_file.h"
#include "io/volume_reader.h"
#include "render/export.h"
#include "render/recipe_json.h"
#include "render/frame_renderer.h"
#include "render/label_styles.h"

namespace angio {

namespace {

ImageWindow imageWindowFrom(const std::string& text) {
  const auto v = parseNumberList(text, 4, "--image-window", "4 numbers left,right,bottom,top (mm)");
  const ImageWindow window{v[0], v[1], v[2], v[3]};
  if (const std::string problem = imageWindowProblem(window); !problem.empty())
    throw std::invalid_argument("--image-window: " + problem);
  return window;
}

RenderParams paramsFrom(const RenderOptions& o, const TransferFunction& tf) {
  RenderParams p;
  p.axis = *parseAxis(o.axis);
  p.angleDeg = o.angleDeg;
  p.sampling = qualitySampling(*parseQuality(o.quality));
  if (o.isd) p.sampling.isd = *o.isd;
  if (o.osd) p.sampling.osd = *o.osd;
  if (o.ert) p.sampling.ert = *o.ert;
  if (o.filter) p.sampling.filter = *parseFilter(*o.filter);
  p.sampling.preintegrated = o.preintegrated;
  if (o.initialStep && !o.adaptive) throw std::invalid_argument("--initial-step needs --adaptive");
  if (o.adaptive) {
    p.sampling.adaptive = AdaptiveIntegration{};
    p.sampling.adaptive->tolerance = *o.adaptive;
    if (o.initialStep) p.sampling.adaptive->initialStep = *o.initialStep;
    if (o.mip) throw std::invalid_argument("--adaptive is for DVR, not --mip");
  }
  if ((o.oracleTolerance || o.rayLevels) && !o.adaptiveSampling)
    throw std::invalid_argument("--oracle-tolerance and --ray-levels need --adaptive-sampling");
  if (o.adaptiveSampling) {
    if (o.adaptive) throw std::invalid_argument("--adaptive-sampling and --adaptive exclude each other");
    if (o.mip) throw std::invalid_argument("--adaptive-sampling is for DVR, not --mip");
    p.sampling.adaptiveSampling = AdaptiveSampling{};
    p.sampling.adaptiveSampling->levels = *o.adaptiveSampling;
    p.sampling.adaptiveSampling->rayLevels =
        o.rayLevels.value_or(std::max(*o.adaptiveSampling, p.sampling.adaptiveSampling->rayLevels));
    if (p.sampling.adaptiveSampling->rayLevels < *o.adaptiveSampling)
      throw std::invalid_argument("--ray-levels must be at least --adaptive-sampling");
    if (o.oracleTolerance) p.sampling.adaptiveSampling->tolerance = *o.oracleTolerance;
  }
  if (o.shading) p.shading.enabled = *o.shading == "on";
  if (o.ka) p.shading.ka = *o.ka;
  if (o.kd) p.shading.kd = *o.kd;
  if (o.mip) p.compositing = Compositing::mip;
  p.mip.window = o.window.value_or(tf.mipWindow);
  p.mip.level = o.level.value_or(tf.mipLevel);
  p.clipping = clippingFrom(o.clipping);
  if (o.imageWindow) p.window = imageWindowFrom(*o.imageWindow);
  return p;
}

// Paths as absolute ones, so the sidecar works from any directory.
std::string absolutePath(const std::string& path) {
  return path.empty() ? path : std::filesystem::absolute(path).lexically_normal().string();
}

void applyLabelOptions(const RenderOptions& o, std::vector<LabelStyle>& styles) {
  if (!o.hide.empty() && o.labels.empty())
    throw std::invalid_argument("--hide needs --labels (a label volume)");
  hideLabels(styles, o.hide);
  if (o.showRemoved) styles = withRemovedShown(std::move(styles));
}

RenderRecipe sidecarFrom(const RenderOptions& o) {
  if (o.volume.empty() || o.out.empty())
    throw std::invalid_argument("render needs VOLUME and --out (or --params SIDECAR.json)");
  RenderRecipe s;
  s.vesselGlyph = vesselGlyphRecipe(o.vesselGlyph, o.tf);
  s.hybrid = hybridCprRecipe(o.vesselGlyph);
  if (s.vesselGlyph && o.mip) throw std::invalid_argument("--mip cannot be combined with --centerlines");
  if (s.vesselGlyph && o.adaptive)
    throw std::invalid_argument("--adaptive cannot be combined with --centerlines (VesselGlyph)");
  if (s.vesselGlyph && o.adaptiveSampling)
    throw std::invalid_argument(
        "--adaptive-sampling cannot be combined with --centerlines (VesselGlyph)");
  s.dataset = absolutePath(o.volume);
  s.labels = absolutePath(o.labels);
  s.quality = parseQuality(o.quality);
  s.raycaster = o.reference ? Raycaster::reference : Raycaster::fast;
  s.tf = loadPresetOrFile(o.tf);
  applyLabelOptions(o, s.tf.labels);
  s.params = paramsFrom(o, s.tf);
  return s;
}

Centerlines loadCenterlines(const RenderRecipe& sidecar, const Volume& volume) {
  if (!sidecar.vesselGlyph) return {};
  CenterlineLoadOptions load;
  load.warn = printWarning;
  Centerlines centerlines =
      toVolumeFrame(loadCenterlines(sidecar.vesselGlyph->centerlines, load), volume);
  checkCenterlinesInside(centerlines, volume, load);
  return centerlines;
}

struct RenderedImage {
  Image image;
  double seconds = 0;
};

// Loads the volume (and centerlines) and renders. The volume goes when this returns, before the
// image is written: the writer (its module, the 8-bit copy, the encoder) then adds to the image
// alone instead of to the volume as well.
RenderedImage renderFromFile(const RenderRecipe& sidecar, const std::filesystem::path& out) {
  const Volume volume = loadVolumeWithProgress(sidecar.dataset, sidecar.labels).volume;
  const Centerlines centerlines = loadCenterlines(sidecar, volume);
  checkImageSize(makeViewGeometry(volume, sidecar.params), out);
  const auto start = std::chrono::steady_clock::now();
  RenderedImage rendered;
  {
    ProgressLine progress("rendering");
    rendered.image =
        renderRecipe(volume, centerlines, sidecar, {.progress = std::ref(progress)}, printWarning);
  }
  rendered.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return rendered;
}

// Loads the volume (and centerlines), renders, writes `out` and its sidecar (image = out).
void renderToFile(const RenderRecipe& sidecar, const std::filesystem::path& out) {
  requireWritableTarget(out);  // before loading and rendering
  requireWritableTarget(sidecarPathFor(out));
  const RenderedImage rendered = renderFromFile(sidecar, out);
  writeImageAndSidecar(rendered.image, out, sidecar);
  std::printf("wrote %s (%dx%d, rendered in %.2f s) and %s\n", out.string().c_str(),
              rendered.image.width, rendered.image.height, rendered.seconds,
              sidecarPathFor(out).string().c_str());
}

}  // namespace

int runRender(const RenderOptions& options) {
  if (options.params.empty()) {
    renderToFile(sidecarFrom(options), options.out);
    return 0;
  }
  const RenderRecipe sidecar = loadRenderSidecar(options.params);
  renderToFile(sidecar, options.out.empty() ? sidecar.image : options.out);
  return 0;
}

}  // namespace angio
