#pragma once
// The Vessels section's runtime state: the tracer of the shown dataset (made on first use, with
// the section's contrast settings), the one tracer job at a time and the clicks waiting for it,
// the undo and redo stacks of path-list changes, the last problem. The paths themselves are the
// document's (VesselsState). Drawn by gui/panel_vessels.cpp, run by gui/app_vessels.cpp.
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "gui/background_job.h"
#include "gui/panel_vessels.h"
#include "gui/vessel_trace_job.h"

namespace angio {

// One undo (or redo) step: the path list before the change.
struct VesselsStep {
  std::vector<VesselPath> paths;
  std::string what;
};

struct VesselsPanel {
  VesselsPanelUi ui;
  std::unique_ptr<VesselTracer> tracer;  // reads the shown volume; used by `job` only
  BackgroundJob<TraceOutcome> job;
  std::string jobWhat;
  std::deque<TraceRequest> queued;        // run one after another
  bool fieldAsked = false;                // the whole volume's lumen field was asked of this tracer
  std::optional<ContrastRange> contrast;  // the tracer's, as the last job left it
  std::vector<VesselsStep> undo, redo;
  std::string problem;   // the tracer's last one-line problem
  std::string error;     // a file's
  bool focused = false;  // the last click was in the section (or on the image, tracing): keys undo
};

}  // namespace angio
