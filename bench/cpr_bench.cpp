#include "bench/cpr_bench.h"
#include "bench/timing.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>

#include <tbb/global_control.h>
#include <tbb/info.h>

namespace angio {

CenterlinePath truncatePath(const CenterlinePath& path, double lengthMm) {
  const std::vector<double> arc = arcLengthsMm(path);
  if (lengthMm <= 0 || arc.empty() || arc.back() <= lengthMm) return path;
  CenterlinePath cut{path.name, {}};
  std::size_t n = 0;
  for (; n < path.points.size() && arc[n] < lengthMm; ++n) cut.points.push_back(path.points[n]);
  const CenterlinePoint& a = path.points[n - 1];
  const CenterlinePoint& b = path.points[n];
  const double t = (lengthMm - arc[n - 1]) / (arc[n] - arc[n - 1]);
  cut.points.push_back(
      {glm::mix(a.positionMm, b.positionMm, t), a.radiusMm + t * (b.radiusMm - a.radiusMm)});
  return cut;
}

CprBenchReport runCprBench(const Volume& volume, const CenterlinePath& path,
                           const CprBenchSettings& settings) {
  std::optional<tbb::global_control> limit;
  if (settings.threads > 0) {
    limit.emplace(tbb::global_control::max_allowed_parallelism, settings.threads);
  }
  const std::vector<CenterlinePath> paths{truncatePath(path, settings.pathLengthMm)};
  const ViewGeometry view = cprView(volume, settings.axis, settings.angleDeg, settings.pixelMm);
  CprSettings cprSettings;
  cprSettings.mode = settings.mode;
  cprSettings.widthMm = settings.widthMm;
  std::vector<double> total, layoutOnly;
  CprLayout layout;
  for (int run = 0; run < std::max(settings.runs, 1); ++run) {
    const auto start = BenchClock::now();
    layout = layoutCpr(paths, view, cprSettings);
    layoutOnly.push_back(msSince(start));
    const std::vector<float> hu = resampleCpr(volume, layout, settings.resampler);
    if (settings.display) displayCpr(layout, hu, CprDisplay{});
    total.push_back(msSince(start));
  }
  CprBenchReport report;
  report.path = path.name;
  report.mode = toString(settings.mode);
  report.resampler = toString(settings.resampler);
  report.pathLengthMm = pathLengthMm(paths.front());
  report.width = layout.width;
  report.height = layout.height;
  report.threads = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
  report.runs = int(total.size());
  report.medianMs = median(total);
  report.minMs = *std::min_element(total.begin(), total.end());
  report.maxMs = *std::max_element(total.begin(), total.end());
  report.medianLayoutMs = median(layoutOnly);
  return report;
}

std::string formatCprBench(const CprBenchReport& r) {
  char line[512];
  std::snprintf(line, sizeof line,
                "%s CPR of '%s' (%.1f mm), %d x %d pixels, %s, %d threads, %d runs: "
                "median %.2f ms (min %.2f, max %.2f; layout %.2f)\n",
                r.mode.c_str(), r.path.c_str(), r.pathLengthMm, r.width, r.height, r.resampler.c_str(),
                r.threads, r.runs, r.medianMs, r.minMs, r.maxMs, r.medianLayoutMs);
  return line;
}

}  // namespace angio
