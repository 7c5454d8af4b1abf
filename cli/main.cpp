// The `angioray` command line: parses options and dispatches to gui/commands.h. No work here.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/number_checks.h"
#include "core/render_params.h"
#include "io/library_messages.h"

namespace {

// ITK's and GDCM's own printing stays off the terminal, where the user reads one line per problem;
// ANGIORAY_LIBRARY_MESSAGES=1 shows it (one line each) when a developer needs it.
// ITK's and GDCM's own messages are shown (one line each) only when asked for.
angio::LibraryMessageSink libraryMessageSink() {
  const char* wanted = std::getenv("ANGIORAY_LIBRARY_MESSAGES");
  const bool show = wanted && std::string(wanted) == "1";
  return [show](const std::string& line) {
    if (show) std::fprintf(stderr, "angioray: library: %s\n", line.c_str());
  };
}

// An exception's text on one line (library texts may hold several).
std::string folded(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

void addInfo(CLI::App& app, angio::InfoOptions& o) {
  auto* cmd = app.add_subcommand("info", "Print dimensions, spacing, orientation and HU statistics");
  cmd->add_option("VOLUME", o.volume, "Volume file or DICOM folder")->required();
  cmd->add_option("--labels", o.labels, "Label volume on the same grid (4-bit labels)");
  cmd->add_option("--tf", o.tf, "Also report the fraction of voxels this TF makes visible");
}

void addRender(CLI::App& app, angio::RenderOptions& o) {
  auto* cmd = app.add_subcommand("render", "Render a volume to an image file (.png, .tif, .exr)");
  cmd->add_option("VOLUME", o.volume, "Volume file or DICOM folder (required without --params)");
  auto* out = cmd->add_option("--out,-o", o.out,
                              "Output image (.png 8-bit, .tif 16-bit, .exr float); "
                              "a JSON sidecar goes beside it (OUT.json)");
  cmd->add_option("--labels", o.labels, "Label volume on the same grid");
  cmd->add_option("--tf", o.tf, "TF preset id or name, or a TF JSON file")->capture_default_str();
  cmd->add_option("--axis", o.axis, "Rotation axis")
      ->check(CLI::IsMember({"i", "j", "k"}))
      ->capture_default_str();
  cmd->add_option("--angle", o.angleDeg, "Rotation angle in degrees")->capture_default_str();
  cmd->add_option("--quality", o.quality, "Quality level (sampling defaults)")
      ->check(CLI::IsMember({"fast", "medium", "high"}))
      ->capture_default_str();
  cmd->add_option("--isd", o.isd, "Image sampling distance (voxel units)")
      ->check(angio::numberAtLeast(angio::kMinSamplingDistance));
  cmd->add_option("--osd", o.osd, "Object sampling distance (voxel units)")
      ->check(angio::numberAtLeast(angio::kMinSamplingDistance));
  cmd->add_option("--filter", o.filter, "Reconstruction filter")
      ->check(CLI::IsMember({"nearest", "trilinear", "mean"}));
  cmd->add_flag("--preintegrated", o.preintegrated,
                "Pre-integrated classification: each segment between samples classified by the TF's "
                "integral over its densities (an approximation that keeps thin shells at larger --osd)");
  cmd->add_option("--adaptive", o.adaptive,
                  "Error-controlled adaptive integration along each ray with this relative tolerance "
                  "(c_tol) instead of samples every --osd (an approximation; DVR without VesselGlyph)")
      ->check(angio::numberBetween(1e-6, 1));
  cmd->add_option("--initial-step", o.initialStep,
                  "Adaptive integration: the first intervals' length in voxels (default 2); nothing "
                  "thicker than half of it is missed")
      ->check(angio::numberBetween(0.125, 64));
  cmd->add_option("--adaptive-sampling", o.adaptiveSampling,
                  "Adaptive sampling in 3-D with this many levels (rays up to 2^levels apart across the "
                  "image, synthesised between, where an oracle finds the TF smooth; pre-integrated; "
                  "an approximation, DVR without VesselGlyph or labels with their own TF)")
      ->check(CLI::Range(0, angio::kMaxAdaptiveLevels));
  cmd->add_option("--ray-levels", o.rayLevels,
                  "Adaptive sampling: samples up to 2^this apart along rays where the oracle allows "
                  "(default 6, at least --adaptive-sampling)")
      ->check(CLI::Range(0, angio::kMaxAdaptiveLevels));
  cmd->add_option("--oracle-tolerance", o.oracleTolerance,
                  "Adaptive sampling: how much the TF's opacity (per voxel) may change over a block of "
                  "4^3 voxels that is still sampled sparsely (default 0.02)")
      ->check(angio::numberBetween(0, 1e6));
  cmd->add_option("--shading", o.shading, "Headlight diffuse shading")
      ->check(CLI::IsMember({"on", "off"}));
  cmd->add_option("--ka", o.ka, "Ambient coefficient")->check(angio::numberBetween(0, 10));
  cmd->add_option("--kd", o.kd, "Diffuse coefficient")->check(angio::numberBetween(0, 10));
  cmd->add_option("--ert", o.ert, "Early ray termination opacity (1 = off)")
      ->check(angio::numberBetween(0, 1));
  cmd->add_flag("--mip", o.mip, "Maximum intensity projection instead of DVR");
  cmd->add_option("--window", o.window, "MIP window width (HU)")->check(angio::numberAbove(0));
  cmd->add_option("--level", o.level, "MIP window centre (HU)");
  cmd->add_option("--image-window", o.imageWindow,
                  "Render only this part of the image: left,right,bottom,top in mm about the image "
                  "centre (right and up positive), the whole image's pixels there (as a zoomed view "
                  "and its export)");
  cmd->add_flag("--reference", o.reference, "Use the plain reference raycaster (same image, slower)");
  cmd->add_option("--hide", o.hide,
                  "Cut a label out of the render (bone, table, a label number 1-15 or a name "
                  "from the TF's labels); repeatable");
  cmd->add_flag("--show-removed", o.showRemoved, "Render hidden labels translucent instead");
  angio::addVesselGlyphOptions(*cmd, o.vesselGlyph);
  angio::addClippingOptions(*cmd, o.clipping);
  auto* params = cmd->add_option("--params", o.params,
                                 "Render again what this sidecar (IMAGE.json) "
                                 "describes, to --out or its image");
  for (CLI::Option* option : cmd->get_options())
    if (option != params && option != out && option != cmd->get_help_ptr()) params->excludes(option);
}

void addCpr(CLI::App& app, angio::CprOptions& o) {
  auto* cmd = app.add_subcommand("cpr", "Curved planar reformation of centerline paths to an image");
  cmd->add_option("VOLUME", o.volume, "Volume file or DICOM folder")->required();
  cmd->add_option("--centerlines", o.centerlines, "Centerlines (.vtp, .mrk.json, .csv)")->required();
  cmd->add_option("--out,-o", o.out, "Output image (.png 8-bit, .tif 16-bit, .exr float)")->required();
  cmd->add_option("--path", o.path, "Path index, or all (side by side, sharing the trunk)")
      ->capture_default_str();
  cmd->add_option("--mode", o.mode, "CPR projection")
      ->check(CLI::IsMember({"projected", "stretched", "straightened"}))
      ->capture_default_str();
  cmd->add_option("--axis", o.axis, "View rotation axis")
      ->check(CLI::IsMember({"i", "j", "k"}))
      ->capture_default_str();
  cmd->add_option("--angle", o.angleDeg, "View angle in degrees (turns the vector of interest)")
      ->capture_default_str();
  cmd->add_option("--width", o.widthMm,
                  "Lateral extent in mm (default 60): straightened: width per "
                  "path; stretched: width / 2 beside the centerline; projected: "
                  "band around it (default: whole rows)")
      ->check(angio::numberAbove(0));
  cmd->add_option("--pixel", o.pixelMm, "Pixel size in mm (default: the voxel unit)")
      ->check(angio::numberAbove(0));
  auto* window =
      cmd->add_option("--window", o.window, "Grey window width (HU)")->check(angio::numberAbove(0));
  auto* level = cmd->add_option("--level", o.level, "Grey window centre (HU)");
  window->needs(level);
  level->needs(window);
  auto* preset = cmd->add_option("--window-preset", o.windowPreset, "Grey window preset")
                     ->check(CLI::IsMember({"cta-lumen", "calcium"}));
  auto* tf = cmd->add_option("--tf", o.tf, "Color through this TF preset or file instead of grey");
  tf->excludes(window)->excludes(level)->excludes(preset);
  cmd->add_flag("!--no-overlay", o.overlay, "Leave out the centerline marker and the ruler");
  cmd->add_option("--resampler", o.resampler, "trilinear (exact) or opencv-remap (comparison)")
      ->check(CLI::IsMember({"trilinear", "opencv-remap"}))
      ->capture_default_str();
  cmd->add_option("--bench", o.benchRuns, "Also time the CPR this many times (median, min, max)")
      ->check(angio::numberAtLeast(0));
  cmd->add_option("--bench-length", o.benchLengthMm, "Cut each path to this length for --bench (mm)")
      ->check(angio::numberAbove(0))
      ->capture_default_str();
}

// The phantom's style: realistic (organs, trabecular bone, correlated noise; arterial or
// portal-venous phase) or simple (as before).
void addStyleOption(CLI::App* cmd, std::string& style, const std::string& flag) {
  cmd->add_option(flag, style,
                  "Phantom style: realistic (arterial phase: organs, trabecular bone, small vessels, "
                  "correlated noise), portal-venous (the same ~70 s after injection: veins enhanced, "
                  "vessels and organs at 100-190 HU) or simple (clean tissue, white noise)")
      ->check(CLI::IsMember({"realistic", "portal-venous", "simple"}))
      ->capture_default_str();
}

void addPhantom(CLI::App& app, angio::PhantomOptionsCli& o) {
  auto* cmd = app.add_subcommand("phantom", "Generate the peripheral run-off CTA phantom");
  cmd->add_option("OUT", o.out, "Output volume (.mha, .nrrd, .nii.gz)")->required();
  cmd->add_option("--size", o.size, "Voxels as IxJxK")->capture_default_str();
  addStyleOption(cmd, o.style, "--style");
  cmd->add_option("--seed", o.seed, "Noise seed")->capture_default_str();
  cmd->add_option("--centerlines", o.centerlines, "Also write ground-truth centerlines (.csv)");
  cmd->add_option("--labels", o.labels,
                  "Also write the ground-truth label volume (uint8: 1 bone, 2 table; .nrrd, .mha, "
                  ".nii.gz)");
}

void addSegment(CLI::App& app, angio::SegmentOptionsCli& o) {
  auto* cmd = app.add_subcommand(
      "segment", "Label bone (1) and the table (2) from the density alone, to a label volume");
  cmd->add_option("VOLUME", o.volume, "Volume file or DICOM folder")->required();
  cmd->add_flag("--bone", o.bone, "Label bone (without --bone or --table: both)");
  cmd->add_flag("--table", o.table, "Label the scanner table");
  cmd->add_option("--labels", o.labels, "Existing label volume on the same grid (user labels kept)");
  cmd->add_option("--centerlines", o.centerlines,
                  "Centerlines (.vtp, .mrk.json, .csv) whose lumen never becomes bone");
  cmd->add_option("--out,-o", o.out,
                  "Output labels: .seg.nrrd (3D Slicer, named segments) or a uint8 label volume "
                  "(.nrrd, .mha, .nii.gz)")
      ->required();
}

void addTrace(CLI::App& app, angio::TraceOptionsCli& o) {
  auto* cmd = app.add_subcommand(
      "trace", "Trace vessel centerlines through the contrast-filled lumen, to a centerline file");
  cmd->add_option("VOLUME", o.volume, "Volume file or DICOM folder")->required();
  cmd->add_option(
      "--points", o.points,
      "Points \"x,y,z;x,y,z[;...]\" in mm (LPS, as centerline files): start, waypoints, end");
  cmd->add_option("--voxels", o.voxels, "The points as voxel indices \"i,j,k;i,j,k[;...]\"");
  cmd->add_flag("--downstream", o.downstream,
                "From the one point, follow the lumen to all its ends (a whole run-off tree)");
  cmd->add_option("--labels", o.labels, "Label volume: labelled bone and table are never lumen");
  cmd->add_option("--tissue-hu", o.tissueHu, "Density around the vessels (default 50 HU)");
  cmd->add_option(
      "--calcium-hu", o.calciumHu,
      "Density where calcium begins (default: as far above the lumen as tissue is below, twice)");
  cmd->add_option("--step", o.stepMm, "Point spacing in mm (default 0.5)");
  cmd->add_option("--compare", o.compare,
                  "Reference centerlines: print how far the traced ones lie from them");
  cmd->add_option("--out,-o", o.out, "Output centerlines: .mrk.json (3D Slicer), .vtp (vmtk) or .csv")
      ->required();
}

void addBench(CLI::App& app, angio::BenchOptionsCli& o) {
  auto* cmd = app.add_subcommand("bench", "Time the raycasters over many angles (median, min, max)");
  cmd->add_option("VOLUME", o.volume, "Volume (default: the generated phantom)");
  cmd->add_option("--size", o.size, "Phantom voxels as IxJxK when no VOLUME")->capture_default_str();
  addStyleOption(cmd, o.style, "--style");
  cmd->add_option("--tf", o.tf, "TF preset or file")->capture_default_str();
  cmd->add_option("--axis", o.axis, "Rotation axis")
      ->check(CLI::IsMember({"i", "j", "k"}))
      ->capture_default_str();
  cmd->add_option("--angles", o.angles, "Angles per level")
      ->check(CLI::Range(1, 3600))
      ->capture_default_str();
  cmd->add_option("--threads", o.threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  cmd->add_flag("--reference", o.reference, "Also time the reference raycaster (slow)");
  cmd->add_flag("!--no-contributions", o.contributions, "Skip the technique-off rows");
  cmd->add_flag("--profile", o.profile,
                "Also count where each level's samples go (skipped, evaluated, visible, faint, "
                "ERT) and the CPU ns per evaluated sample");
  cmd->add_option("--json", o.json, "Also write the results as JSON");
  cmd->add_option("--levels", o.levels, "Only these levels (fast, medium, medium-trilinear, high)")
      ->check(CLI::IsMember({"fast", "medium", "medium-trilinear", "high"}));
  cmd->add_option("--centerlines", o.centerlines,
                  "Also time VesselGlyph frames with these centerlines (default: the phantom's)");
  cmd->add_option("--labels", o.labels, "Label volume for VOLUME: also time frames with labels");
  cmd->add_option("--hide", o.hide, "Labels hidden in those frames (default: bone); repeatable");
  cmd->add_flag("--glyph-intervals", o.glyphIntervals,
                "Time only VesselGlyph interval construction at medium quality: 20 synthetic "
                "paths of 1000 points, or --centerlines");
  cmd->add_flag("--trace", o.trace,
                "Time only vessel tracing: the lumen field, traces between the ends of the phantom's "
                "paths (or --centerlines) cut to 600 mm, the 3-D pick");
  cmd->add_flag("--slices", o.slices,
                "Time only the slice view's images: each orientation stepped through --angles "
                "slices");
  cmd->add_flag("--tiles", o.tiles,
                "Time only the slice tiles' summaries (after a load, an axis or a label change): "
                "plain, and with --labels or else every voxel above 300 HU labelled; --angles runs");
  cmd->add_flag("--skip-adaptive", o.skipAdaptive,
                "With --approximations: leave out the adaptive integration rows (seconds to a minute "
                "per frame at 512x512x1200)");
  cmd->add_flag("--only-adaptive-sampling", o.onlyAdaptiveSampling,
                "With --approximations: only the adaptive sampling rows, with the level's exact and "
                "pre-integrated rows at its own osd");
  cmd->add_flag("--only-refinement", o.onlyRefinement,
                "With --approximations: only the image refinement rows, with the level's exact and "
                "pre-integrated rows at its own osd");
  cmd->add_flag("--approximations", o.approximations,
                "Time only the approximations against the exact images: per level, osd x1 ... x4 "
                "post- and pre-integrated, PSNR against the level's exact image and the converged "
                "one (osd / 4); --angles 6 is plenty");
}

void addDemo(CLI::App& app, angio::DemoOptions& o) {
  auto* cmd = app.add_subcommand(
      "demo", "Generate the phantom and render it at the three quality levels (the default job)");
  cmd->add_option("--out-dir", o.outDir, "Where the PNGs go")->capture_default_str();
  cmd->add_option("--size", o.size, "Phantom voxels as IxJxK")->capture_default_str();
  addStyleOption(cmd, o.style, "--style");
}

void addGui(CLI::App& app, angio::GuiOptions& o) {
  auto* cmd = app.add_subcommand(
      "gui", "The workstation: rotate, tune the transfer function, progressive quality");
  cmd->add_option("VOLUME", o.volume, "Volume file or DICOM folder (default: the phantom)");
  cmd->add_option("--phantom-size", o.phantomSize,
                  "Phantom voxels as IxJxK when no VOLUME (modest by default, for a quick start)")
      ->capture_default_str();
  addStyleOption(cmd, o.phantomStyle, "--phantom-style");
  cmd->add_option("--tf", o.tf, "TF preset id or name, or a TF JSON file")->capture_default_str();
  cmd->add_option("--axis", o.axis, "Rotation axis")
      ->check(CLI::IsMember({"i", "j", "k"}))
      ->capture_default_str();
  cmd->add_option("--angle", o.angleDeg, "Start angle in degrees")->capture_default_str();
  cmd->add_flag("--mip", o.mip, "Start in MIP mode");
  cmd->add_option("--size", o.size, "Window size WxH in pixels")->capture_default_str();
  cmd->add_flag("--headless", o.headless, "No window: OSMesa software rendering of the same UI");
  cmd->add_option("--script", o.script,
                  "Headless: JSON list of input steps (move, click, drag, "
                  "wheel, key, wait_ms, wait_level, screenshot, state)");
  cmd->add_option("--screenshot", o.screenshot,
                  "Screenshot at the end (headless without --script: once the high image is shown)");
  cmd->add_option("--state-out", o.stateOut, "Write the app's state and timings as JSON at the end");
  cmd->add_option("--timeout", o.timeoutSeconds, "Headless: seconds to wait for a quality level")
      ->check(angio::numberAbove(0))
      ->capture_default_str();
  cmd->add_option("--session", o.session,
                  "Restore a saved session (its dataset unless VOLUME is "
                  "given, view, TF, levels, panels)");
  cmd->add_option("--quit-after", o.quitAfterSeconds, "Window: close after this many seconds")
      ->check(angio::numberAtLeast(0));
  cmd->add_option("--centerlines", o.centerlines,
                  "Centerlines (.vtp, .mrk.json, .csv) for the VesselGlyph panel");
  cmd->add_option("--motion-budget", o.motionBudgetMs,
                  "ms the first level may take while dragging: the finest image sampling between "
                  "the medium and fast levels' that fits (0: always the fast level)")
      ->check(angio::numberBetween(0, 1000))
      ->capture_default_str();
  cmd->add_option("--labels", o.labels,
                  "Label volume or Slicer .seg.nrrd on VOLUME's grid, read at start");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"angioray " ANGIORAY_VERSION " - CPU volume rendering for CT angiography"};
  app.failure_message(angio::oneLineFailure);
  app.set_version_flag("--version", ANGIORAY_VERSION);
  angio::InfoOptions info;
  angio::RenderOptions render;
  angio::CprOptions cpr;
  angio::PhantomOptionsCli phantom;
  angio::DemoOptions demo;
  angio::BenchOptionsCli bench;
  angio::SegmentOptionsCli segment;
  angio::TraceOptionsCli trace;
  angio::GuiOptions gui;
  addInfo(app, info);
  addRender(app, render);
  addCpr(app, cpr);
  addPhantom(app, phantom);
  addDemo(app, demo);
  addSegment(app, segment);
  addTrace(app, trace);
  addBench(app, bench);
  addGui(app, gui);
  app.require_subcommand(0, 1);
  angio::requireFiniteNumbers(app);
  CLI11_PARSE(app, argc, argv);  // its messages go to std::cerr, so before the libraries get it

  const angio::LibraryMessageRoute libraryMessages(libraryMessageSink());
  try {
    if (app.got_subcommand("info")) return angio::runInfo(info);
    if (app.got_subcommand("render")) return angio::runRender(render);
    if (app.got_subcommand("cpr")) return angio::runCpr(cpr);
    if (app.got_subcommand("phantom")) return angio::runPhantom(phantom);
    if (app.got_subcommand("segment")) return angio::runSegment(segment);
    if (app.got_subcommand("trace")) return angio::runTrace(trace);
    if (app.got_subcommand("bench")) return angio::runBench(bench);
    if (app.got_subcommand("gui")) return angio::runGui(gui);
    if (app.got_subcommand("demo")) return angio::runDemo(demo);
    // No subcommand: the workstation when there is a display, else the headless demo.
    if (angio::canOpenWindow()) return angio::runGui(gui);
    return angio::runDemo(demo);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "angioray: error: %s\n", folded(error.what()).c_str());
    return 1;
  }
}
