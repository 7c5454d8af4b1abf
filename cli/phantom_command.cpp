// `angioray phantom`: write the run-off CTA phantom (and its ground-truth centerlines and labels).
#include <cstdio>
#include <functional>

#include "phantom/phantom.h"
#include "cli/commands.h"
#include "cli/progress_line.h"
#include "cli/size_option.h"
#include "io/centerline_csv.h"
#include "io/label_volume_file.h"
#include "io/volume_writer.h"
#include "vessel/centerline.h"

namespace angio {

int runPhantom(const PhantomOptionsCli& options) {
  PhantomOptions phantomOptions;
  phantomOptions.dims = parseSize(options.size);
  phantomOptions.seed = options.seed;
  phantomOptions.groundTruthLabels = !options.labels.empty();
  Phantom phantom;
  {
    ProgressLine progress("generating phantom");
    phantom = generatePhantom(phantomOptions, std::ref(progress));
  }
  writeVolume(phantom.volume, options.out);
  std::printf("wrote %s\n", options.out.c_str());
  if (!options.labels.empty()) {
    writeLabelVolume(options.labels, phantom.volume);
    std::printf("wrote %s\n", options.labels.c_str());
  }
  if (!options.centerlines.empty()) {
    writeCenterlinesCsv(phantom.centerlines, options.centerlines);
    std::printf("wrote %s (%zu paths)\n", options.centerlines.c_str(), phantom.centerlines.paths.size());
  }
  return 0;
}

}  // namespace angio
