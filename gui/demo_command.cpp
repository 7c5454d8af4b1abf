// The main job on the embedded default: the phantom at the three quality levels, as PNGs.
#include <cstdio>
#include <filesystem>
#include <functional>

#include "core/phantom.h"
#include "gui/commands.h"
#include "gui/progress_line.h"
#include "gui/render_job.h"
#include "io/tf_file.h"

namespace angio {

int runDemo(const DemoOptions& options) {
  PhantomOptions phantomOptions;
  phantomOptions.dims = parseSize(options.size);
  Phantom phantom;
  {
    ProgressLine progress("generating phantom " + options.size);
    phantom = generatePhantom(phantomOptions, std::ref(progress));
  }
  std::filesystem::create_directories(options.outDir);
  const TransferFunction tf = loadPresetOrFile("cta-vessels-bone");
  for (Quality quality : {Quality::fast, Quality::medium, Quality::high}) {
    RenderDescription description;
    description.dataset = "phantom " + options.size;
    description.transferFunction = tf.name;
    description.quality = quality;
    description.params.angleDeg = 20;  // a slight oblique view shows depth better than AP
    description.params.sampling = qualitySampling(quality);
    const auto out = std::filesystem::path(options.outDir) / ("phantom-" + std::string(toString(quality)) + ".png");
    renderAndExport(phantom.volume, tf, description, out);
  }
  std::printf("no GUI yet: the three quality levels are in %s/\n",
              std::filesystem::absolute(options.outDir).string().c_str());
  return 0;
}

}  // namespace angio
