#pragma once
// The Vessels section: the Trace tool (a click on the view adds a control point to the selected
// path, snapped to the lumen's centre, and traces the path through its points again; "move" puts
// the selected point where the next click is; "Trace downstream" takes the next click as the seed
// of a tree), the contrast settings, the path list (select, rename, delete), the selected path's
// control points, undo and redo, save and load. Drawing only: it returns what the user asked for.
#include <optional>
#include <string>

#include "gui/panel_widgets.h"
#include "gui/workstation.h"
#include "vessel/lumen_field.h"

namespace angio {

// What the next click on the view does while the tool is on.
enum class TraceClick { addPoint, movePoint, downstream };

struct VesselsPanelUi {
  bool traceTool = false;
  TraceClick click = TraceClick::addPoint;
  int selectedPath = -1;     // the path clicks extend; -1: the next click starts a new one
  int selectedPoint = -1;    // of the selected path
  bool fixedTissue = false;  // else the tracer's (vessel/vessel_tracing.h TraceSettings)
  double tissueHu = 300;
  bool fixedCalcium = false;  // else the tracer's: twice the lumen's margin above it
  double calciumHu = 3000;
  std::string path = "vessels.mrk.json";  // the save / load field
  std::string rename;                     // the selected path's name as typed
  bool renaming = false;                  // the name field has the keyboard
};

struct VesselsPanelInfo {
  bool hasVolume = false;
  bool busy = false;     // a tracer job runs
  std::string busyWhat;  // e.g. "lumen field"
  double progress = -1;  // < 0: unknown (the seconds show instead)
  double seconds = 0;
  int queued = 0;  // clicks waiting for the tracer
  std::optional<ContrastRange> contrast;
  bool canUndo = false, canRedo = false;
  std::string undoWhat, redoWhat;
  std::string file;  // loaded or saved
  bool unsaved = false;
  std::string problem;  // the tracer's last one-line problem
  std::string error;    // a file's
};

struct VesselsPanelResult {
  std::optional<VesselPathsEdit> edit;  // a rename or delete, one undo step
  std::string what;                     // ... described
  bool removePoint = false;             // ui.selectedPoint of ui.selectedPath
  bool settingsChanged = false;         // tissue or calcium HU: a new tracer
  bool cancel = false;
  bool undo = false, redo = false;
  bool save = false, load = false;              // ui.path
  bool browseSave = false, browseLoad = false;  // the file browser first
};

VesselsPanelResult drawVesselsPanel(const VesselsState& vessels, VesselsPanelUi& ui,
                                    const VesselsPanelInfo& info, WidgetRects& rects);

}  // namespace angio
