// `angioray cpr`: volume + centerlines -> curved planar reformation image (vessel/cpr.h).
#include <chrono>
#include <cstdio>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "bench/cpr_bench.h"
#include "cli/load_volume.h"
#include "cli/commands.h"
#include "cli/progress_line.h"
#include "io/atomic_write.h"
#include "io/centerline_file.h"
#include "io/image_export.h"
#include "io/input_error.h"
#include "io/tf_file.h"
#include "io/volume_reader.h"
#include "vessel/cpr.h"

namespace angio {

namespace {

std::string number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// The display the options ask for, and its one-line description for the metadata.
CprDisplay displayFrom(const CprOptions& o, std::string& description) {
  CprDisplay display;
  display.centerlineMarker = display.ruler = o.overlay;
  if (!o.tf.empty()) {
    display.tf = loadPresetOrFile(o.tf);
    description = "tf " + display.tf->name;
    return display;
  }
  if (!o.windowPreset.empty()) {
    const std::optional<WindowLevel> preset = windowPreset(o.windowPreset);
    if (!preset) throw std::invalid_argument("unknown window preset '" + o.windowPreset + "'");
    display.windowLevel = *preset;
  }
  if (o.window) display.windowLevel = {*o.window, *o.level};
  description =
      "window " + number(display.windowLevel.window) + " level " + number(display.windowLevel.level);
  return display;
}

// Errors about the paths are errors of the centerline file.
template <typename Work>
auto aboutCenterlines(const std::string& file, Work&& work) {
  try {
    return work();
  } catch (const CprPathError& error) {
    throw InputError(file, error.what());
  }
}

void runBenchmark(const Volume& volume, const std::vector<CenterlinePath>& paths, const CprOptions& o,
                  double pixelMm) {
  CprBenchSettings settings;
  settings.runs = o.benchRuns;
  settings.mode = *parseCprMode(o.mode);
  settings.pixelMm = pixelMm;
  settings.widthMm = o.widthMm.value_or(kDefaultCprWidthMm);
  settings.pathLengthMm = o.benchLengthMm;
  settings.axis = *parseAxis(o.axis);
  settings.angleDeg = o.angleDeg;
  settings.resampler = *parseCprResampler(o.resampler);
  for (const CenterlinePath& path : paths) {
    std::printf("%s", formatCprBench(runCprBench(volume, path, settings)).c_str());
  }
}

}  // namespace

int runCpr(const CprOptions& o) {
  requireWritableTarget(o.out);  // before loading and resampling
  std::string displayDescription;
  const CprDisplay display = displayFrom(o, displayDescription);
  const LoadedVolume loaded = loadVolumeWithProgress(o.volume);
  const Volume& volume = loaded.volume;
  CenterlineLoadOptions loadOptions;
  loadOptions.warn = printWarning;
  const Centerlines centerlines = toVolumeFrame(loadCenterlines(o.centerlines, loadOptions), volume);
  const std::vector<CenterlinePath> paths =
      aboutCenterlines(o.centerlines, [&] { return selectPaths(centerlines, o.path); });

  const double pixelMm = o.pixelMm.value_or(voxelUnit(volume));
  const Axis axis = *parseAxis(o.axis);
  const ViewGeometry view = cprView(volume, axis, o.angleDeg, pixelMm);
  CprSettings settings;
  settings.mode = *parseCprMode(o.mode);
  settings.widthMm = o.widthMm;
  const CprResampler resampler = *parseCprResampler(o.resampler);
  const auto start = std::chrono::steady_clock::now();
  const Cpr cpr = aboutCenterlines(o.centerlines,
                                   [&] { return computeCpr(volume, paths, view, settings, resampler); });
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  for (const std::string& warning : cpr.layout.warnings) printWarning(o.centerlines + ": " + warning);

  CprDescription description;
  description.dataset = o.volume;
  description.centerlines = o.centerlines;
  for (const CenterlinePath& path : paths) description.pathNames.push_back(path.name);
  description.axis = axis;
  description.angleDeg = o.angleDeg;
  description.display = displayDescription;
  description.resampler = resampler;
  exportImage(displayCpr(cpr.layout, cpr.hu, display), o.out, cprMetadata(cpr.layout, description));
  std::printf("wrote %s: %s CPR of %zu path%s, %d x %d pixels, %g mm per pixel (%.1f ms)\n",
              o.out.c_str(), o.mode.c_str(), paths.size(), paths.size() == 1 ? "" : "s",
              cpr.layout.width, cpr.layout.height, cpr.layout.pixelMm, ms);
  if (o.benchRuns > 0) runBenchmark(volume, paths, o, pixelMm);
  return 0;
}

}  // namespace angio
