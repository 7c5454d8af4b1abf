#include "gui/vessel_trace_job.h"

#include <algorithm>

namespace angio {

namespace {

std::vector<glm::dvec3> inVolumeFrame(const Volume& volume, const std::vector<glm::dvec3>& physical) {
  std::vector<glm::dvec3> points;
  for (const glm::dvec3& p : physical) points.push_back(volumeFrameMm(volume, p));
  return points;
}

CenterlinePath physicalPath(const Volume& volume, CenterlinePath path) {
  Centerlines framed{"", CenterlineFrame::volume, {std::move(path)}};
  return toPhysicalFrame(framed, volume).paths.front();
}

// The path through `points` (volume frame, snapped): traced when there are two or more.
TraceOutcome traced(VesselTracer& tracer, const Volume& volume, VesselPath path,
                    const std::vector<glm::dvec3>& points, JobControl& control) {
  TraceOutcome outcome;
  path.controlPointsMm.clear();
  for (const glm::dvec3& p : points) path.controlPointsMm.push_back(physicalFrameMm(volume, p));
  path.centerline = {path.name, {}};
  if (points.size() >= 2) {
    TracedPath result = tracer.trace(points, &control.cancel);
    if (!result.path) {
      outcome.problem = result.problem;
      outcome.cancelled = control.cancel.load();
      return outcome;
    }
    result.path->name = path.name;
    path.centerline = physicalPath(volume, std::move(*result.path));
  }
  outcome.paths.push_back(std::move(path));
  return outcome;
}

TraceOutcome downstream(VesselTracer& tracer, const Volume& volume, const TraceRequest& request,
                        JobControl& control) {
  TraceOutcome outcome;
  const TracedTree tree = tracer.traceDownstream(request.clickMm, &control.cancel,
                                                 [&control](double f) { control.progress.store(f); });
  outcome.problem = tree.problem;
  outcome.cancelled = control.cancel.load();
  if (!tree.problem.empty() || outcome.cancelled) return outcome;
  const Centerlines physical = toPhysicalFrame(tree.centerlines, volume);
  for (const CenterlinePath& path : physical.paths)
    outcome.paths.push_back({"tree " + path.name, {}, path});
  outcome.what = "trace downstream: " + std::to_string(outcome.paths.size()) + " paths";
  return outcome;
}

std::string actionText(const TraceRequest& request, const std::string& name) {
  switch (request.action) {
    case TraceAction::addPoint: return "add a point to " + name;
    case TraceAction::movePoint:
      return "move point " + std::to_string(request.point + 1) + " of " + name;
    case TraceAction::removePoint:
      return "remove point " + std::to_string(request.point + 1) + " of " + name;
    case TraceAction::downstream: return "trace downstream";
    case TraceAction::prepare: break;
  }
  return "lumen field";
}

TraceOutcome changePoints(VesselTracer& tracer, const Volume& volume, const TraceRequest& request,
                          const VesselPath& path, JobControl& control) {
  std::vector<glm::dvec3> points = inVolumeFrame(volume, path.controlPointsMm);
  const bool inRange = request.point >= 0 && request.point < int(points.size());
  if (request.action != TraceAction::addPoint && !inRange) return {request, {}, "no such point"};
  if (request.action == TraceAction::removePoint) {
    points.erase(points.begin() + request.point);
    return traced(tracer, volume, path, points, control);
  }
  const SnappedPoint snapped = tracer.snap(request.clickMm, &control.cancel);
  if (!snapped.positionMm) return {request, {}, snapped.problem, "", {}, control.cancel.load()};
  if (request.action == TraceAction::movePoint) points[request.point] = *snapped.positionMm;
  else points.push_back(*snapped.positionMm);
  return traced(tracer, volume, path, points, control);
}

}  // namespace

TraceOutcome runTrace(VesselTracer& tracer, const Volume& volume, const TraceRequest& request,
                      const VesselPath& path, JobControl& control) {
  TraceOutcome outcome;
  if (request.action == TraceAction::prepare) {
    outcome.cancelled = !tracer.prepare(wholeVolume(volume), &control.cancel);
    if (outcome.cancelled && !control.cancel.load()) outcome.problem = "no contrast range yet";
  } else if (request.action == TraceAction::downstream) {
    outcome = downstream(tracer, volume, request, control);
  } else {
    outcome = changePoints(tracer, volume, request, path, control);
  }
  outcome.request = request;
  if (outcome.what.empty()) outcome.what = actionText(request, path.name);
  outcome.contrast = tracer.contrast();
  return outcome;
}

std::vector<VesselPath> withOutcome(std::vector<VesselPath> paths, const TraceOutcome& outcome) {
  const int at = outcome.request.path;
  const bool replaces = outcome.request.action != TraceAction::downstream && at >= 0 &&
                        at < int(paths.size()) && outcome.paths.size() == 1;
  if (replaces) paths[at] = outcome.paths.front();
  else paths.insert(paths.end(), outcome.paths.begin(), outcome.paths.end());
  return paths;
}

std::string newPathName(const std::vector<VesselPath>& paths) {
  for (int n = 1;; ++n) {
    const std::string name = "path " + std::to_string(n);
    if (std::none_of(paths.begin(), paths.end(), [&](const VesselPath& p) { return p.name == name; }))
      return name;
  }
}

std::vector<VesselPath> importedPaths(const Centerlines& physical) {
  std::vector<VesselPath> paths;
  for (const CenterlinePath& path : physical.paths) paths.push_back({path.name, {}, path});
  return paths;
}

}  // namespace angio
