// `angioray bench`: load or generate the volume, run bench/frame_bench, print and save.
#include <cstdio>
#include <fstream>
#include <functional>

#include "bench/approximation_bench.h"
#include "bench/frame_bench.h"
#include "bench/slice_bench.h"
#include "bench/tile_bench.h"
#include "bench/trace_bench.h"
#include "bench/vessel_glyph_bench.h"
#include "phantom/phantom.h"
#include "phantom/phantom_anatomy.h"
#include "cli/commands.h"
#include "cli/progress_line.h"
#include "cli/size_option.h"
#include "io/atomic_write.h"
#include "io/centerline_file.h"
#include "io/input_error.h"
#include "io/tf_file.h"
#include "io/volume_reader.h"
#include "render/label_styles.h"

namespace angio {

namespace {

// The volume, and the phantom's ground-truth centerlines when it is the phantom.
Phantom benchVolume(const BenchOptionsCli& options) {
  if (!options.labels.empty() && options.volume.empty())
    throw std::invalid_argument("--labels needs VOLUME (write the phantom with `angioray phantom`)");
  if (!options.volume.empty())
    return {readVolume(options.volume, {.labelPath = options.labels}).volume, {}};
  PhantomOptions phantom;
  phantom.dims = parseSize(options.size);
  phantom.style = parseStyle(options.style);
  ProgressLine progress("generating phantom " + options.size);
  return generatePhantom(phantom, std::ref(progress));
}

// --centerlines, else the phantom's own; none for a volume file without --centerlines.
std::optional<Centerlines> benchCenterlines(const BenchOptionsCli& options, const Phantom& data) {
  if (!options.centerlines.empty())
    return toVolumeFrame(loadCenterlines(options.centerlines), data.volume);
  if (!data.centerlines.paths.empty()) return toVolumeFrame(data.centerlines, data.volume);
  return std::nullopt;
}

void writeText(const std::string& text, const std::filesystem::path& path) {
  writeAtomically(path, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp);
    out << text << '\n';
    if (!out) throw InputError(path, "cannot write");
  });
}

// --glyph-intervals: the interval benchmark case, 20 paths of 1000 points (a vessel tree in vmtk's
// layout, then 20 independent tortuous paths as a stress case), or the --centerlines given.
int runGlyphIntervalBench(const BenchOptionsCli& options, const Volume& volume) {
  GlyphBenchSettings settings;
  settings.angles = options.angles;
  settings.axis = *parseAxis(options.axis);
  settings.threads = options.threads;
  const auto run = [&](const std::string& what, const Centerlines& centerlines) {
    std::printf("%s: %s", what.c_str(),
                formatGlyphBench(runVesselGlyphBench(volume, centerlines, {}, settings)).c_str());
  };
  if (!options.centerlines.empty()) {
    run(options.centerlines, toVolumeFrame(loadCenterlines(options.centerlines), volume));
    return 0;
  }
  run("tree of 20 paths x 1000 points", syntheticVesselTree(volume, 20, 1000));
  run("20 independent paths x 1000 points", syntheticCenterlines(volume, 20, 1000));
  return 0;
}

// The styles of the label rows: each of `hide` (default: bone) hidden.
std::vector<LabelStyle> hiddenLabels(const std::vector<std::string>& hide) {
  std::vector<LabelStyle> styles;
  hideLabels(styles, hide.empty() ? std::vector<std::string>{"bone"} : hide);
  return styles;
}

}  // namespace

int runBench(const BenchOptionsCli& options) {
  if (options.glyphIntervals && options.volume.empty()) {
    Volume geometry;  // the phantom's geometry without voxels: intervals need no more
    geometry.dims = parseSize(options.size);
    geometry.spacing = phantom::kBoxSizeMm / glm::dvec3(geometry.dims);
    return runGlyphIntervalBench(options, geometry);
  }
  const TransferFunction tf = loadPresetOrFile(options.tf);
  const Phantom data = benchVolume(options);
  const Volume& volume = data.volume;
  if (options.glyphIntervals) return runGlyphIntervalBench(options, volume);
  if (options.approximations) {
    ApproximationSettings settings;
    settings.angles = options.angles;
    settings.axis = *parseAxis(options.axis);
    settings.threads = options.threads;
    settings.levels = options.levels;
    if (options.skipAdaptive || options.onlyAdaptiveSampling) settings.adaptive.clear();
    if (options.onlyAdaptiveSampling || options.onlyRefinement)
      settings.osdScales = {1};  // exact and pre-integrated
    if (options.onlyAdaptiveSampling) settings.refinement.clear();
    if (options.onlyRefinement) {
      settings.adaptive.clear();
      settings.adaptiveSampling.clear();
    }
    std::printf("%s", formatApproximationBench(runApproximationBench(volume, tf, settings)).c_str());
    return 0;
  }
  if (options.slices) {
    std::printf("%s", formatSliceBench(runSliceBench(volume, options.angles)).c_str());
    return 0;
  }
  if (options.tiles) {
    Volume plain = volume;
    for (Voxel& v : plain.voxels) v = Voxel(densityOf(v));
    const Volume labelled = options.labels.empty() ? labelledAbove(volume, 300) : volume;
    std::printf("%s",
                formatTileBench(runTileBench(plain, labelled, *parseAxis(options.axis), options.angles))
                    .c_str());
    return 0;
  }
  if (options.trace) {
    const auto centerlines = benchCenterlines(options, data);
    if (!centerlines)
      throw std::invalid_argument("--trace needs --centerlines for VOLUME (their ends are the clicks)");
    std::printf(
        "%s",
        formatTraceBench(runTraceBench(volume, *centerlines, tf, {.threads = options.threads})).c_str());
    return 0;
  }
  BenchSettings settings;
  settings.vesselTree = benchCenterlines(options, data);
  settings.angles = options.angles;
  settings.axis = *parseAxis(options.axis);
  settings.threads = options.threads;
  settings.withReference = options.reference;
  settings.withContributions = options.contributions;
  settings.profile = options.profile;
  settings.levels = options.levels;
  if (!options.labels.empty()) settings.labels = hiddenLabels(options.hide);
  BenchReport report = runFrameBench(volume, tf, settings);
  report.dataset = options.volume.empty() ? "phantom " + options.size : options.volume;
  std::printf("%s", formatTable(report).c_str());
  if (!options.json.empty()) writeText(toJson(report), options.json);
  return 0;
}

}  // namespace angio
