#include "bench/slice_bench.h"

#include <algorithm>
#include <cstdio>

#include "bench/timing.h"

namespace angio {

namespace {

constexpr SliceOrientation kOrientations[] = {SliceOrientation::axial, SliceOrientation::coronal,
                                              SliceOrientation::sagittal};

// The cursor through voxel `index` along `axis`, at the volume's centre otherwise.
glm::dvec3 cursorAt(const Volume& volume, int axis, int index) {
  glm::dvec3 cursor = glm::dvec3(volume.dims - 1) * volume.spacing * 0.5;
  cursor[axis] = index * volume.spacing[axis];
  return cursor;
}

}  // namespace

std::vector<SliceBenchRow> runSliceBench(const Volume& volume, int runs) {
  std::vector<SliceBenchRow> rows;
  const WindowLevel cta{600, 250};
  for (const SliceOrientation orientation : kOrientations) {
    const int axis = fixedAxisOf(orientation), count = volume.dims[axis];
    std::vector<double> times;
    SliceBenchRow row{orientation};
    for (int run = 0; run < runs; ++run) {
      const int index = (count / 2 + run) % count;
      const auto start = BenchClock::now();
      const SliceImage slice = extractSlice(volume, orientation, cursorAt(volume, axis, index), cta);
      times.push_back(msSince(start));
      row.width = slice.width;
      row.height = slice.height;
    }
    row.runs = runs;
    row.medianMs = median(times);
    row.minMs = *std::min_element(times.begin(), times.end());
    row.maxMs = *std::max_element(times.begin(), times.end());
    rows.push_back(row);
  }
  return rows;
}

std::string formatSliceBench(const std::vector<SliceBenchRow>& rows) {
  std::string text = "slice      pixels        runs  median ms  min ms  max ms\n";
  for (const SliceBenchRow& row : rows) {
    char line[128];
    std::snprintf(line, sizeof line, "%-9s  %5d x %-5d  %4d  %9.2f  %6.2f  %6.2f\n",
                  sliceOrientationName(row.orientation), row.width, row.height, row.runs, row.medianMs,
                  row.minMs, row.maxMs);
    text += line;
  }
  return text;
}

}  // namespace angio
