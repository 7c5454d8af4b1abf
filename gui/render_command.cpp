// `angioray render`: volume + TF + view -> image file.
#include <cstdio>
#include <functional>

#include "gui/commands.h"
#include "gui/progress_line.h"
#include "gui/render_job.h"
#include "io/tf_file.h"
#include "io/volume_reader.h"

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

void printWarning(const std::string& warning) {
  std::fprintf(stderr, "angioray: warning: %s\n", warning.c_str());
}

}  // namespace

int runRender(const RenderOptions& options) {
  const TransferFunction tf = loadPresetOrFile(options.tf);
  ReadOptions read;
  read.labelPath = options.labels;
  read.warn = printWarning;
  ProgressLine loading("loading " + options.volume);
  read.progress = std::ref(loading);
  const LoadedVolume loaded = readVolume(options.volume, read);
  RenderDescription description;
  description.dataset = options.volume;
  description.transferFunction = tf.name;
  description.quality = parseQuality(options.quality);
  description.params = paramsFrom(options, tf);
  renderAndExport(loaded.volume, tf, description, options.out,
                  options.reference ? Raycaster::reference : Raycaster::fast);
  return 0;
}

}  // namespace angio
