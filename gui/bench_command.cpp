// `angioray bench`: load or generate the volume, run bench/frame_bench, print and save.
#include <cstdio>
#include <fstream>
#include <functional>

#include "bench/frame_bench.h"
#include "core/phantom.h"
#include "gui/commands.h"
#include "gui/progress_line.h"
#include "gui/render_job.h"
#include "io/atomic_write.h"
#include "io/input_error.h"
#include "io/tf_file.h"
#include "io/volume_reader.h"

namespace angio {

namespace {

Volume benchVolume(const BenchOptionsCli& options) {
  if (!options.volume.empty()) return readVolume(options.volume).volume;
  PhantomOptions phantom;
  phantom.dims = parseSize(options.size);
  ProgressLine progress("generating phantom " + options.size);
  return generatePhantom(phantom, std::ref(progress)).volume;
}

void writeText(const std::string& text, const std::filesystem::path& path) {
  writeAtomically(path, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp);
    out << text << '\n';
    if (!out) throw InputError(path, "cannot write");
  });
}

}  // namespace

int runBench(const BenchOptionsCli& options) {
  const TransferFunction tf = loadPresetOrFile(options.tf);
  const Volume volume = benchVolume(options);
  BenchSettings settings;
  settings.angles = options.angles;
  settings.axis = *parseAxis(options.axis);
  settings.threads = options.threads;
  settings.withReference = options.reference;
  settings.withContributions = options.contributions;
  BenchReport report = runFrameBench(volume, tf, settings);
  report.dataset = options.volume.empty() ? "phantom " + options.size : options.volume;
  std::printf("%s", formatTable(report).c_str());
  if (!options.json.empty()) writeText(toJson(report), options.json);
  return 0;
}

}  // namespace angio
