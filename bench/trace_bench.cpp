#include "bench/trace_bench.h"

#include <algorithm>
#include <cstdio>

#include <tbb/global_control.h>

#include "bench/cpr_bench.h"
#include "bench/timing.h"
#include "core/label_tables.h"
#include "core/ray_pick.h"
#include "core/view_geometry.h"
#include "vessel/centerline_comparison.h"
#include "vessel/vessel_tracing.h"

namespace angio {

namespace {

Timing timingOf(const std::vector<double>& ms) {
  return {median(ms), *std::min_element(ms.begin(), ms.end()), *std::max_element(ms.begin(), ms.end())};
}

TraceBenchRow fieldRow(const Volume& volume, const Centerlines& centerlines, int runs) {
  std::vector<double> ms;
  for (int run = 0; run < runs; ++run) {
    VesselTracer tracer(volume);
    tracer.widenContrastFor(centerlines.paths.front().points.front().positionMm);
    const auto start = BenchClock::now();
    tracer.prepare(wholeVolume(volume));
    ms.push_back(msSince(start));
  }
  return {"lumen field, whole volume", timingOf(ms), ""};
}

TraceBenchRow traceRow(VesselTracer& tracer, const CenterlinePath& truth, int runs) {
  std::vector<double> ms;
  TracedPath traced;
  for (int run = 0; run < runs; ++run) {
    const auto start = BenchClock::now();
    traced = tracer.trace({truth.points.front().positionMm, truth.points.back().positionMm});
    ms.push_back(msSince(start));
  }
  char detail[200];
  if (!traced.path) {
    std::snprintf(detail, sizeof detail, "failed: %s", traced.problem.c_str());
  } else {
    const CenterlineDeviation d = deviationFrom(*traced.path, truth);
    std::snprintf(detail, sizeof detail, "%.0f mm; mean %.2f mm, p95 %.2f, radius %.1f%%",
                  pathLengthMm(*traced.path), d.meanMm, d.p95Mm, 100 * d.meanRadiusError);
  }
  return {"trace " + truth.name, timingOf(ms), detail};
}

// A click on the middle of the first path, seen from pickAngles angles about k.
TraceBenchRow pickRow(const Volume& volume, const CenterlinePath& path, const TransferFunction& tf,
                      int angles) {
  const TfTable table = buildTable(tf);
  const LabelTables labels(tf.labels);
  const glm::dvec3 target = path.points[path.points.size() / 2].positionMm;
  std::vector<double> ms;
  int hits = 0;
  for (int a = 0; a < angles; ++a) {
    RenderParams params;
    params.angleDeg = 360.0 * a / angles;
    params.sampling = qualitySampling(Quality::high);
    const glm::dvec2 imagePoint = imagePointOf(makeViewGeometry(volume, params), target);
    const auto start = BenchClock::now();
    const auto picked =
        pickPoint(volume, {nullptr, nullptr, nullptr, &table, &labels}, params, imagePoint);
    ms.push_back(msSince(start));
    hits += picked.has_value();
  }
  return {"pick (high level sampling)", timingOf(ms),
          std::to_string(hits) + " of " + std::to_string(angles) + " hit"};
}

}  // namespace

std::vector<TraceBenchRow> runTraceBench(const Volume& volume, const Centerlines& centerlines,
                                         const TransferFunction& tf,
                                         const TraceBenchSettings& settings) {
  std::optional<tbb::global_control> threads;
  if (settings.threads > 0)
    threads.emplace(tbb::global_control::max_allowed_parallelism, settings.threads);
  std::vector<TraceBenchRow> rows;
  if (centerlines.paths.empty()) return rows;
  rows.push_back(fieldRow(volume, centerlines, settings.fieldRuns));
  VesselTracer tracer(volume);
  tracer.widenContrastFor(centerlines.paths.front().points.front().positionMm);
  tracer.prepare(wholeVolume(volume));
  for (const CenterlinePath& path : centerlines.paths) {
    const CenterlinePath cut =
        settings.pathLengthMm > 0 ? truncatePath(path, settings.pathLengthMm) : path;
    rows.push_back(traceRow(tracer, cut, settings.traceRuns));
  }
  rows.push_back(pickRow(volume, centerlines.paths.front(), tf, settings.pickAngles));
  return rows;
}

std::string formatTraceBench(const std::vector<TraceBenchRow>& rows) {
  std::string text = "what                                      median ms    min ms    max ms  detail\n";
  char line[400];
  for (const TraceBenchRow& row : rows) {
    std::snprintf(line, sizeof line, "%-40s %10.1f %9.1f %9.1f  %s\n", row.what.c_str(),
                  row.timing.medianMs, row.timing.minMs, row.timing.maxMs, row.detail.c_str());
    text += line;
  }
  return text;
}

}  // namespace angio
