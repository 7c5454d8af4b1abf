// `angioray phantom`: write the run-off CTA phantom (and its ground-truth centerlines).
#include <cstdio>
#include <functional>

#include "core/phantom.h"
#include "gui/commands.h"
#include "gui/progress_line.h"
#include "gui/render_job.h"
#include "io/centerline_csv.h"
#include "io/volume_writer.h"
#include "vessel/centerline.h"

namespace angio {

int runPhantom(const PhantomOptionsCli& options) {
  PhantomOptions phantomOptions;
  phantomOptions.dims = parseSize(options.size);
  phantomOptions.seed = options.seed;
  Phantom phantom;
  {
    ProgressLine progress("generating phantom");
    phantom = generatePhantom(phantomOptions, std::ref(progress));
  }
  writeVolume(phantom.volume, options.out);
  std::printf("wrote %s\n", options.out.c_str());
  if (!options.centerlines.empty()) {
    writeCenterlinesCsv(centerlinesFromPhantom(phantom.paths), options.centerlines);
    std::printf("wrote %s (%zu paths)\n", options.centerlines.c_str(), phantom.paths.size());
  }
  return 0;
}

}  // namespace angio
