#pragma once
// The subcommands of the `angioray` command line: option structs filled by main.cpp's parser and
// the functions that run them. Each returns the process exit code; errors throw (main reports).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli/clipping_options.h"
#include "cli/vessel_glyph_options.h"

namespace angio {

struct InfoOptions {
  std::string volume;
  std::string labels;
  std::string tf;  // if set: also the fraction of voxels this TF makes visible
};
int runInfo(const InfoOptions& options);

// Explicit values override the quality level's defaults.
struct RenderOptions {
  std::string volume;
  std::string labels;
  std::string out;
  std::string tf = "cta-vessels";
  std::string axis = "k";
  double angleDeg = 0;
  std::string quality = "high";
  std::optional<double> isd, osd, ert, ka, kd;
  std::optional<std::string> filter;
  bool preintegrated = false;                   // pre-integrated classification (an approximation)
  std::optional<double> adaptive, initialStep;  // adaptive integration: c_tol, first step (voxels)
  std::optional<int> adaptiveSampling;          // adaptive sampling (seed 003): its levels
  std::optional<int> rayLevels;                 // and along rays
  std::optional<double> oracleTolerance;        // and its oracle's tolerance
  std::optional<std::string> shading;           // "on" | "off"
  bool mip = false;
  std::optional<double> window, level;
  std::optional<std::string> imageWindow;  // "left,right,bottom,top", mm about the image centre
  bool reference = false;                  // the plain reference raycaster instead of the fast one
  std::vector<std::string> hide;           // labels (names or numbers) cut out of the render
  bool showRemoved = false;                // hidden labels translucent instead of cut out
  VesselGlyphCliOptions vesselGlyph;       // VesselGlyph and DVR+CPR hybrid (gui/vessel_glyph_options.h)
  ClippingCliOptions clipping;             // crop box, clip plane, thick slab (cli/clipping_options.h)
  std::string params;  // a render sidecar to reproduce (then only --out may be given)
};
// Writes the image and its sidecar (render/recipe_json.h), or re-renders a sidecar's image.
int runRender(const RenderOptions& options);

// `angioray cpr`: curved planar reformation of centerline paths (vessel/cpr.h).
struct CprOptions {
  std::string volume;
  std::string centerlines;
  std::string out;
  std::string path = "all";  // "all" or one path index
  std::string mode = "straightened";
  std::string axis = "k";
  double angleDeg = 0;
  std::optional<double> widthMm;
  std::optional<double> pixelMm;  // default: the voxel unit (isd 1)
  std::optional<double> window, level;
  std::string windowPreset;  // "cta-lumen" | "calcium"
  std::string tf;            // color through this TF instead of grey
  bool overlay = true;       // centerline marker and arc-length ruler
  std::string resampler = "trilinear";
  int benchRuns = 0;           // > 0: also time the CPR this many times
  double benchLengthMm = 400;  // ... of each path cut to this length
};
int runCpr(const CprOptions& options);

struct PhantomOptionsCli {
  std::string out;
  std::string size = "512x512x1200";
  std::string style = "realistic";  // PhantomStyle by name
  std::uint64_t seed = 1;
  std::string centerlines;
  std::string labels;  // also write the ground-truth label volume (bone 1, table 2)
};
int runPhantom(const PhantomOptionsCli& options);

// `angioray segment`: bone (label 1) and table (label 2) from the density alone, to a label volume.
struct SegmentOptionsCli {
  std::string volume;
  std::string labels;       // existing labels: user labels (3..15) are kept
  std::string centerlines;  // protect their lumen
  std::string out;
  bool bone = false;  // neither flag: both
  bool table = false;
};
int runSegment(const SegmentOptionsCli& options);

// `angioray trace`: centerlines between points (start, waypoints, end) or downstream of one.
struct TraceOptionsCli {
  std::string volume;
  std::string labels;  // bone and table labels: never lumen
  std::string points;  // "x,y,z;x,y,z;..." physical (LPS mm)
  std::string voxels;  // the same as voxel indices
  bool downstream = false;
  std::optional<double> tissueHu, calciumHu, stepMm;
  std::string out;      // .mrk.json, .vtp or .csv
  std::string compare;  // a reference centerline file: print how far the traced paths lie from it
};
int runTrace(const TraceOptionsCli& options);

// `angioray bench`: frame times of the raycasters (bench/frame_bench.h); no VOLUME = the phantom.
struct BenchOptionsCli {
  std::string volume;
  std::string size = "512x512x1200";
  std::string style = "realistic";  // of the phantom when no VOLUME
  std::string tf = "cta-vessels";
  std::string axis = "k";
  int angles = 36;
  int threads = 0;
  bool reference = false;
  bool contributions = true;
  bool profile = false;             // also where each level's samples go (bench/frame_profile.h)
  std::vector<std::string> levels;  // empty = all
  std::string centerlines;          // adds VesselGlyph rows (the phantom's own when no VOLUME)
  std::string labels;               // a label volume for VOLUME: adds label rows
  std::vector<std::string> hide;    // the labels those rows hide (default: bone)
  std::string json;
  bool glyphIntervals =
      false;                  // time only VesselGlyph interval construction (bench/vessel_glyph_bench.h)
  bool trace = false;         // time only vessel tracing (bench/trace_bench.h)
  bool slices = false;        // time only the slice view's images (bench/slice_bench.h)
  bool tiles = false;         // time only the slice tiles' summaries (bench/tile_bench.h)
  bool skipAdaptive = false;  // --approximations without the adaptive integration rows
  bool onlyAdaptiveSampling = false;  // --approximations: only the adaptive sampling rows
  bool onlyRefinement = false;        // --approximations: only the image refinement rows
  bool approximations = false;  // time and compare the approximations (bench/approximation_bench.h)
};
int runBench(const BenchOptionsCli& options);

// The main job on the embedded default: generate the phantom, render it at the three quality
// levels, write PNGs and say where they are.
struct DemoOptions {
  std::string outDir = "angioray-out";
  std::string size = "512x512x1200";
  std::string style = "realistic";
};
int runDemo(const DemoOptions& options);

// `angioray gui`: the workstation window, or its headless twin (OSMesa, scripted input,
// screenshots). No volume = the phantom at phantomSize.
struct GuiOptions {
  std::string volume;
  std::string phantomSize = "256x256x600";
  std::string phantomStyle = "realistic";
  std::string tf = "cta-vessels-bone";
  std::string axis = "k";
  double angleDeg = 0;
  bool mip = false;
  std::string size = "1280x800";  // window pixels
  bool headless = false;
  std::string script;           // headless: JSON list of input steps (gui/app_script.h)
  std::string screenshot;       // written at the end (window: when it closes)
  std::string stateOut;         // the app's state and runtime numbers as JSON, at the end
  double timeoutSeconds = 300;  // headless: for each wait for a quality level
  double quitAfterSeconds = 0;  // window: close by itself after this long (smoke tests)
  std::string session;          // a saved session (gui/session_file.h): its dataset, view, TF, panels
  std::string centerlines;      // loaded into the VesselGlyph panel at start (errors shown there)
  std::string labels;           // a label volume or .seg.nrrd read at start (errors shown there)
  double motionBudgetMs = 40;   // the first level's render time to aim at while dragging; 0: fixed
};
int runGui(const GuiOptions& options);
// A display is there and GLFW can open windows on it.
bool canOpenWindow();

}  // namespace angio
