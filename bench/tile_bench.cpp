#include "bench/tile_bench.h"

#include <algorithm>
#include <cstdio>

#include "bench/timing.h"
#include "core/slice_tiles.h"

namespace angio {

namespace {

double labelledPercentOf(const Volume& volume) {
  std::size_t count = 0;
  for (const Voxel v : volume.voxels) count += labelOf(v) != 0;
  return 100.0 * double(count) / double(std::max<std::size_t>(volume.voxels.size(), 1));
}

template <class Build>
TileBenchRow timeBuilds(const char* what, double labelledPercent, int runs, Build build) {
  TileBenchRow row{what, labelledPercent, runs};
  std::vector<double> wall, cpu;
  for (int run = 0; run < runs; ++run) {
    const double cpuStart = processCpuMs();
    const auto start = BenchClock::now();
    const SliceTiles tiles = build();
    wall.push_back(msSince(start));
    cpu.push_back(processCpuMs() - cpuStart);
  }
  row.medianMs = median(wall);
  row.minMs = *std::min_element(wall.begin(), wall.end());
  row.maxMs = *std::max_element(wall.begin(), wall.end());
  row.medianCpuMs = median(cpu);
  return row;
}

}  // namespace

Volume labelledAbove(const Volume& volume, double hu) {
  Volume labelled = volume;
  const int threshold = densityOfHu(hu);
  for (Voxel& v : labelled.voxels)
    if (densityOf(v) > threshold) v = Voxel(densityOf(v) | 1 << 12);
  return labelled;
}

std::vector<TileBenchRow> runTileBench(const Volume& volume, const Volume& labelled, Axis axis,
                                       int runs) {
  const double percent = labelledPercentOf(labelled);
  std::vector<TileBenchRow> rows{
      timeBuilds("plain", 0.0, runs, [&] { return buildSliceTiles(volume, axis); }),
      timeBuilds("labelled", percent, runs, [&] { return buildSliceTiles(labelled, axis); })};
  if (!overlaySummarisedAbout(axis)) return rows;
  // The labels as a label change's overlay on the volume without them (what a label job builds).
  std::vector<std::size_t> voxels;
  std::vector<std::uint8_t> labels;
  for (std::size_t n = 0; n < labelled.voxels.size(); ++n)
    if (labelOf(labelled.voxels[n]) != labelOf(volume.voxels[n])) {
      voxels.push_back(n);
      labels.push_back(std::uint8_t(labelOf(labelled.voxels[n])));
    }
  rows.push_back(timeBuilds("ahead", percent, runs, [&] {
    return buildSliceTiles(volume, axis, LabelOverlay{voxels, labels});
  }));
  return rows;
}

std::string formatTileBench(const std::vector<TileBenchRow>& rows) {
  std::string text = "tiles     labelled %  runs  median ms  min ms  max ms  median CPU ms\n";
  for (const TileBenchRow& row : rows) {
    char line[128];
    std::snprintf(line, sizeof line, "%-8s  %10.2f  %4d  %9.1f  %6.1f  %6.1f  %13.1f\n",
                  row.what.c_str(), row.labelledPercent, row.runs, row.medianMs, row.minMs, row.maxMs,
                  row.medianCpuMs);
    text += line;
  }
  return text;
}

}  // namespace angio
