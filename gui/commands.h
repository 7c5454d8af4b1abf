#pragma once
// The subcommands of the `angioray` command line: option structs filled by main.cpp's parser and
// the functions that run them. Each returns the process exit code; errors throw (main reports).
#include <cstdint>
#include <optional>
#include <string>

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
  std::optional<std::string> shading;  // "on" | "off"
  bool mip = false;
  std::optional<double> window, level;
  bool reference = false;  // the plain reference raycaster instead of the fast one
};
int runRender(const RenderOptions& options);

struct PhantomOptionsCli {
  std::string out;
  std::string size = "512x512x1200";
  std::uint64_t seed = 1;
  std::string centerlines;
};
int runPhantom(const PhantomOptionsCli& options);

// `angioray bench`: frame times of the raycasters (bench/frame_bench.h); no VOLUME = the phantom.
struct BenchOptionsCli {
  std::string volume;
  std::string size = "512x512x1200";
  std::string tf = "cta-vessels";
  std::string axis = "k";
  int angles = 36;
  int threads = 0;
  bool reference = false;
  bool contributions = true;
  std::string json;
};
int runBench(const BenchOptionsCli& options);

// The main job on the embedded default: generate the phantom, render it at the three quality
// levels, write PNGs and say where they are.
struct DemoOptions {
  std::string outDir = "angioray-out";
  std::string size = "512x512x1200";
};
int runDemo(const DemoOptions& options);

}  // namespace angio
