#pragma once
// What the Vessels section asks the tracer (vessel/vessel_tracing.h) for, run in a BackgroundJob:
// a control point added, moved or removed (the path snapped and traced again through its points),
// the tree downstream of a click, or the lumen field over the whole volume. The job gets the path
// it changes as it is when it starts and gives back the changed path; the app puts it in the list
// (withOutcome) as one undo step. Positions cross into the volume frame here: the tracer works in
// it, the document keeps physical mm.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/volume.h"
#include "gui/background_job.h"
#include "gui/document.h"
#include "vessel/vessel_tracing.h"

namespace angio {

enum class TraceAction { addPoint, movePoint, removePoint, downstream, prepare };

struct TraceRequest {
  TraceAction action = TraceAction::addPoint;
  int path = -1;            // the path it changes, -1 = a new one
  int point = -1;           // move, remove: which control point
  glm::dvec3 clickMm{0.0};  // add, move, downstream: the picked point (volume frame)
};

struct TraceOutcome {
  TraceRequest request;
  std::vector<VesselPath> paths;          // the changed path, or the downstream tree's; none: no change
  std::string problem;                    // the tracer's one line when nothing changes
  std::string what;                       // for the status line and the undo tooltip
  std::optional<ContrastRange> contrast;  // the tracer's range afterwards
  bool cancelled = false;
};

// `path`: the path the request changes as it is now (a new one: empty, named). Uses the tracer
// alone: one such job at a time.
TraceOutcome runTrace(VesselTracer& tracer, const Volume& volume, const TraceRequest& request,
                      const VesselPath& path, JobControl& control);

// The list with the outcome's paths in it: the request's path replaced, or (a new path, a tree,
// a path index that is gone) appended.
std::vector<VesselPath> withOutcome(std::vector<VesselPath> paths, const TraceOutcome& outcome);

// "path N" for the lowest N no path is named.
std::string newPathName(const std::vector<VesselPath>& paths);

// Paths read from a file: no control points (gui/document.h says why).
std::vector<VesselPath> importedPaths(const Centerlines& physical);

}  // namespace angio
