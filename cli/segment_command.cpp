// `angioray segment`: automatic bone and table removal (segment/bone_removal.h) to a label volume.
#include <array>
#include <chrono>
#include <cstdio>
#include <functional>
#include <optional>

#include "cli/commands.h"
#include "cli/load_volume.h"
#include "cli/progress_line.h"
#include "io/centerline_file.h"
#include "io/input_error.h"
#include "io/volume_writer.h"
#include "render/label_styles.h"
#include "segment/bone_removal.h"

namespace angio {

namespace {

void printCounts(const LabelResult& result, const Volume& volume) {
  for (int label = 0; label <= kMaxLabel; ++label) {
    const std::size_t count = result.voxelsPerLabel[label];
    if (count == 0) continue;
    const char* name = label == kBoneLabel ? " (bone)" : label == kTableLabel ? " (table)" : "";
    std::printf("label %d%s: %zu voxels (%.2f%%)\n", label, name, count,
                100.0 * double(count) / double(volume.voxelCount()));
  }
}

}  // namespace

int runSegment(const SegmentOptionsCli& options) {
  requireVolumeTarget(options.out);  // before the minutes of loading and labelling
  LoadedVolume loaded = loadVolumeWithProgress(options.volume, options.labels);
  std::optional<Centerlines> centerlines;
  if (!options.centerlines.empty()) {
    const CenterlineLoadOptions load{.warn = printWarning};
    centerlines = loadCenterlines(options.centerlines, load);
    checkCenterlinesInside(*centerlines, loaded.volume, load);
  }
  if (const std::string warning = calibrationWarning(loaded.volume); !warning.empty())
    printWarning(options.volume + ": " + warning);
  BoneRemovalOptions removal;
  // Neither flag: both, the usual request.
  removal.bone = options.bone || !options.table;
  removal.table = options.table || !options.bone;
  const auto start = std::chrono::steady_clock::now();
  LabelResult result;
  {
    ProgressLine progress("removing bone and table");
    result = removeBoneAndTable(loaded.volume, centerlines ? &*centerlines : nullptr, removal,
                                {.progress = std::ref(progress)});
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  applyLabels(loaded.volume, result.labels);
  std::array<std::uint64_t, kLabelCount> voxels{};
  for (int label = 0; label < kLabelCount; ++label) voxels[label] = result.voxelsPerLabel[label];
  writeLabelFile(options.out, loaded.volume, {}, voxels);
  printCounts(result, loaded.volume);
  std::printf("segmented in %.1f s; wrote %s\n", seconds, options.out.c_str());
  return 0;
}

}  // namespace angio
