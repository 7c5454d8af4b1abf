// `angioray trace`: centerlines from the volume alone (vessel/vessel_tracing.h), between given
// points or downstream of one, to a centerline file.
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string_view>

#include "cli/commands.h"
#include "cli/load_volume.h"
#include "cli/progress_line.h"
#include "io/centerline_file.h"
#include "io/input_error.h"
#include "vessel/centerline_comparison.h"
#include "vessel/vessel_tracing.h"

namespace angio {

namespace {

double parseNumber(std::string_view text, const std::string& flag, std::string_view point) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw std::invalid_argument(flag + ": '" + std::string(point) +
                                "' is not three finite numbers x,y,z");
  return value;
}

glm::dvec3 parsePoint(std::string_view point, const std::string& flag) {
  glm::dvec3 p(0.0);
  std::size_t start = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const std::size_t comma = point.find(',', start);
    if ((axis < 2) == (comma == std::string_view::npos))
      throw std::invalid_argument(flag + ": '" + std::string(point) +
                                  "' is not three finite numbers x,y,z");
    p[axis] = parseNumber(point.substr(start, comma - start), flag, point);
    start = comma + 1;
  }
  return p;
}

// "x,y,z;x,y,z;..." as points.
std::vector<glm::dvec3> parsePoints(const std::string& text, const std::string& flag) {
  std::vector<glm::dvec3> points;
  std::string_view rest = text;
  while (!rest.empty()) {
    const std::size_t semicolon = rest.find(';');
    const std::string_view point = rest.substr(0, semicolon);
    if (!point.empty()) points.push_back(parsePoint(point, flag));
    rest = semicolon == std::string_view::npos ? std::string_view() : rest.substr(semicolon + 1);
  }
  return points;
}

// The clicks in the volume frame: --points are physical (LPS mm, as centerline files hold them),
// --voxels are voxel indices.
std::vector<glm::dvec3> pointsInVolumeFrame(const TraceOptionsCli& options, const Volume& volume) {
  if (options.points.empty() == options.voxels.empty())
    throw std::invalid_argument("give the points with either --points (LPS mm) or --voxels (i,j,k)");
  std::vector<glm::dvec3> points;
  if (!options.points.empty()) {
    for (const glm::dvec3& p : parsePoints(options.points, "--points"))
      points.push_back(volumeFrameMm(volume, p));
  } else {
    for (const glm::dvec3& v : parsePoints(options.voxels, "--voxels"))
      points.push_back(v * volume.spacing);
  }
  // Every point inside the volume before any is traced (volume frame: 0 .. dims x spacing).
  const glm::dvec3 extent = glm::dvec3(volume.dims) * volume.spacing;
  for (std::size_t n = 0; n < points.size(); ++n)
    if (glm::any(glm::lessThan(points[n], glm::dvec3(0))) ||
        glm::any(glm::greaterThan(points[n], extent)))
      throw std::invalid_argument(std::string(options.points.empty() ? "--voxels" : "--points") +
                                  ": point " + std::to_string(n + 1) +
                                  ": the point lies outside the volume");
  const std::size_t needed = options.downstream ? 1 : 2;
  if (points.size() < needed)
    throw std::invalid_argument(options.downstream ? "--downstream needs one point"
                                                   : "a path needs at least two points");
  return points;
}

TraceSettings settingsOf(const TraceOptionsCli& options) {
  TraceSettings settings;
  if (options.tissueHu) settings.tissueHu = *options.tissueHu;
  settings.calciumHu = options.calciumHu;
  if (options.stepMm) {
    if (!std::isfinite(*options.stepMm) || *options.stepMm < 0.1 || *options.stepMm > 5)
      throw std::invalid_argument("--step must be between 0.1 and 5 mm");
    settings.stepMm = *options.stepMm;
  }
  return settings;
}

void printPaths(const Centerlines& traced) {
  for (const CenterlinePath& path : traced.paths) {
    double radius = 0;
    for (const CenterlinePoint& p : path.points) radius += p.radiusMm;
    std::printf("path %s: %zu points, %.1f mm, mean radius %.2f mm\n", path.name.c_str(),
                path.points.size(), pathLengthMm(path),
                path.points.empty() ? 0.0 : radius / double(path.points.size()));
  }
}

// Each traced path against the reference path it lies nearest to.
void printComparison(const Centerlines& traced, const Centerlines& reference) {
  for (const CenterlinePath& path : traced.paths) {
    const CenterlinePath* nearest = nullptr;
    CenterlineDeviation best;
    for (const CenterlinePath& candidate : reference.paths) {
      const CenterlineDeviation d = deviationFrom(path, candidate);
      if (!nearest || d.meanMm < best.meanMm) {
        nearest = &candidate;
        best = d;
      }
    }
    if (!nearest) return;
    const CenterlineDeviation back = deviationFrom(*nearest, path);
    std::printf(
        "path %s vs reference %s: mean %.2f mm, p95 %.2f, max %.2f; reference to path max %.2f mm; "
        "radius error mean %.1f%%, p95 %.1f%%\n",
        path.name.c_str(), nearest->name.c_str(), best.meanMm, best.p95Mm, best.maxMm, back.maxMm,
        100 * best.meanRadiusError, 100 * best.p95RadiusError);
  }
}

}  // namespace

int runTrace(const TraceOptionsCli& options) {
  requireCenterlineTarget(options.out);  // before loading and tracing
  LoadedVolume loaded = loadVolumeWithProgress(options.volume, options.labels);
  const Volume& volume = loaded.volume;
  const std::vector<glm::dvec3> points = pointsInVolumeFrame(options, volume);
  VesselTracer tracer(volume, settingsOf(options));
  const auto start = std::chrono::steady_clock::now();
  Centerlines traced;
  std::string problem;
  if (options.downstream) {
    ProgressLine progress("tracing downstream");
    TracedTree tree = tracer.traceDownstream(points.front(), nullptr, std::ref(progress));
    traced = std::move(tree.centerlines);
    problem = tree.problem;
  } else {
    TracedPath path = tracer.trace(points);
    if (path.path) {
      path.path->name = "1";
      traced = {"traced", CenterlineFrame::volume, {std::move(*path.path)}};
    }
    problem = path.problem;
  }
  if (!problem.empty()) throw InputError(options.volume, problem);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Centerlines physical = toPhysicalFrame(traced, volume);
  saveCenterlines(physical, options.out);
  printPaths(physical);
  if (tracer.contrast())
    std::printf("lumen %.0f..%.0f HU; traced in %.2f s; wrote %s\n", tracer.contrast()->lowHu,
                tracer.contrast()->highHu, seconds, options.out.c_str());
  if (!options.compare.empty()) {
    const CenterlineLoadOptions load{.warn = printWarning};
    printComparison(traced, toVolumeFrame(loadCenterlines(options.compare, load), volume));
  }
  return 0;
}

}  // namespace angio
