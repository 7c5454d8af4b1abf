#pragma once
// Frame-time benchmark of the raycasters: for each quality level, render N angles about one axis
// and report median, min and max ms per frame and samples per frame; then the same with one
// technique switched off at a time ("contribution", thesis fig. 4.9 ff.).
#include <optional>
#include <string>
#include <vector>

#include "bench/frame_profile.h"
#include "core/blocked_volume.h"
#include "core/render_params.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "vessel/centerline.h"

namespace angio {

// Every level has an "all" row, a "clipped" row: that frame with a crop box around the middle
// 80 % of the volume and a clip plane facing the viewer through its centre (the per-ray clip
// intervals, core/clip_interval.h), a "mip" row (MIP through the default window, 250 / 600 HU)
// and, where the TF allows it, a "blocked volume" row (the frame from the blocked volume).
struct BenchSettings {
  int angles = 36;
  Axis axis = Axis::k;
  bool withReference = false;  // also time the reference raycaster (slow)
  bool withContributions = true;
  int threads = 0;                  // 0 = all cores
  std::vector<std::string> levels;  // names of the levels to time; empty = all
  // With centerlines (volume frame): also a "vessel glyph" row per level (thesis ch. 5): focus =
  // the TF within 2x the vessel radius, context = the TF at 30 % opacity in a slab 20 mm in front
  // of and behind the centerline, outside clipped; each frame builds its ray intervals. And a
  // "hybrid cpr" row (thesis fig. 5.4): that frame with the projected CPR of every path composited
  // into the focus's footprint.
  std::optional<Centerlines> vesselTree;
  // Label styles for a volume with labels: a "labels" row per level renders with them, a
  // "labels, own TF" row with every listed label given the main TF as its own (the image without
  // labels, the cost of per-label classification alone), and the re-classification after a label
  // change is timed.
  std::vector<LabelStyle> labels;
  // Also count where each level's samples go (bench/frame_profile.h), in untimed frames at the
  // same angles as its "all" row.
  bool profile = false;
};

// The levels every frame bench times: the three quality levels and medium with trilinear filtering.
struct BenchLevel {
  std::string name;  // "fast", "medium", "medium-trilinear", "high"
  Sampling sampling;

  RenderParams params(Axis axis) const;  // a view about `axis` with this sampling
};
// Those of `wanted` (names; empty: all), in the order above.
std::vector<BenchLevel> benchLevels(const std::vector<std::string>& wanted = {});

// The n-th of `count` angles spread over the full turn, as every timed row renders them.
double benchAngle(int n, int count);

struct FrameTimingRow {
  std::string level;    // "fast", "medium", "high", "medium-trilinear"
  std::string variant;  // "all", "clipped", "reference", "no empty-space skipping", ...
  double medianMs = 0, minMs = 0, maxMs = 0;
  double medianCpuMs = 0;    // CPU time of all threads per frame
  double medianSamples = 0;  // density reconstructions per frame
  int frames = 0;
};

struct InterruptLatency {
  double medianMs = 0, maxMs = 0;
  int frames = 0;  // frames still running when cancelled (the others are left out)
};

struct BenchReport {
  std::string dataset;
  std::string transferFunction;
  glm::ivec3 dims{0};
  double volumeMiB = 0;
  double accelerationMiB = 0;  // slice tiles + classification
  double preprocessMs = 0;     // building the slice tiles for the axis
  double classifyMs = 0;       // classifying them for the TF
  double labelClassifyMs = 0;  // median re-classification after a label change (with labels)
  BlockingReport blocking;     // the blocked volume (built and classified)
  // The "blocked volume" rows' levels whose frame at angle 30 from the blocked volume was not the
  // flat volume's to the bit (a check at full size, beside the unit tests' small volumes).
  std::vector<std::string> blockedImagesDiffering;
  int blockedImagesCompared = 0;
  // High-quality frames cancelled part-way: cancel flag set -> the render returned. `recycled`:
  // in frame memory a previous frame gave back, as the GUI renders once it has shown a high frame;
  // `fresh`: in new memory, as the first high frame after a load.
  InterruptLatency recycledInterrupt, freshInterrupt;
  int threads = 0;
  std::vector<FrameTimingRow> rows;
  std::vector<LevelProfile> profiles;  // with BenchSettings::profile, one per level
};

BenchReport runFrameBench(const Volume& volume, const TransferFunction& tf,
                          const BenchSettings& settings);

std::string formatTable(const BenchReport& report);
std::string toJson(const BenchReport& report);

}  // namespace angio
