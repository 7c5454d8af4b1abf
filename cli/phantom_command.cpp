// `angioray phantom`: write the run-off CTA phantom (and its ground-truth centerlines and labels).
#include <cstdio>
#include <functional>

#include "phantom/phantom.h"
#include "cli/commands.h"
#include "cli/progress_line.h"
#include "cli/size_option.h"
#include "io/atomic_write.h"
#include "io/centerline_file.h"
#include "io/centerline_csv.h"
#include "io/label_volume_file.h"
#include "io/volume_writer.h"
#include "vessel/centerline.h"

namespace angio {

int runPhantom(const PhantomOptionsCli& options) {
  PhantomOptions phantomOptions;
  phantomOptions.dims = parseSize(options.size);
  phantomOptions.seed = options.seed;
  phantomOptions.style = parseStyle(options.style);
  phantomOptions.groundTruthLabels = !options.labels.empty();
  // Every output is checked before minutes of generating.
  requireVolumeTarget(options.out);
  if (!options.labels.empty()) requireVolumeTarget(options.labels);
  if (!options.centerlines.empty()) requireCenterlineTarget(options.centerlines);
  Phantom phantom;
  {
    ProgressLine progress("generating phantom");
    phantom = generatePhantom(phantomOptions, std::ref(progress));
  }
  // The volume and its ground truth appear together or not at all.
  AtomicFileGroup files;
  files.add(options.out, [&](const std::filesystem::path& file) { writeVolume(phantom.volume, file); });
  if (!options.labels.empty())
    files.add(options.labels,
              [&](const std::filesystem::path& file) { writeLabelVolume(file, phantom.volume); });
  if (!options.centerlines.empty())
    files.add(options.centerlines, [&](const std::filesystem::path& file) {
      writeCenterlinesCsv(phantom.centerlines, file);
    });
  files.commit();
  std::printf("wrote %s\n", options.out.c_str());
  if (!options.labels.empty()) std::printf("wrote %s\n", options.labels.c_str());
  if (!options.centerlines.empty())
    std::printf("wrote %s (%zu paths)\n", options.centerlines.c_str(), phantom.centerlines.paths.size());
  return 0;
}

}  // namespace angio
