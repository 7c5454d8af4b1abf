#include "bench/tile_bench.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <numeric>
#include <thread>

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

std::vector<int> allSlicesOf(const Volume& volume, Axis axis) {
  std::vector<int> slices(std::size_t(volume.dims[int(axis)]));
  std::iota(slices.begin(), slices.end(), 0);
  return slices;
}

// Builds in parts, cancelled from another thread at 10, 20, ... 90 % of `buildMs` (cycling over
// the runs); the latency is from the cancel to the build's return.
TileBenchRow timeInterrupts(const Volume& volume, Axis axis, int runs, double buildMs) {
  std::vector<double> latency;
  for (int run = 0; run < runs; ++run) {
    const double fraction = 0.1 * (1 + run % 9);
    SliceTiles tiles = unsummarisedSliceTiles(volume, axis, false);
    std::vector<int> unbuilt = allSlicesOf(volume, axis);
    std::atomic<bool> cancel{false};
    BenchClock::time_point cancelledAt{};
    std::thread canceller([&] {
      std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(fraction * buildMs));
      cancelledAt = BenchClock::now();
      cancel.store(true);
    });
    const bool finished = summariseSliceTiles(tiles, volume, unbuilt, &cancel);
    const BenchClock::time_point returned = BenchClock::now();
    canceller.join();
    if (!finished)
      latency.push_back(std::chrono::duration<double, std::milli>(returned - cancelledAt).count());
  }
  TileBenchRow row{"interrupt", 0.0, int(latency.size())};
  if (latency.empty()) return row;
  row.medianMs = median(latency);
  row.minMs = *std::min_element(latency.begin(), latency.end());
  row.maxMs = *std::max_element(latency.begin(), latency.end());
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
      timeBuilds("labelled", percent, runs, [&] { return buildSliceTiles(labelled, axis); }),
      timeBuilds("in parts", 0.0, runs, [&] {
        SliceTiles tiles = unsummarisedSliceTiles(volume, axis, false);
        std::vector<int> unbuilt = allSlicesOf(volume, axis);
        summariseSliceTiles(tiles, volume, unbuilt, nullptr);
        return tiles;
      })};
  rows.push_back(timeInterrupts(volume, axis, std::max(runs, 9), rows[0].medianMs));
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
