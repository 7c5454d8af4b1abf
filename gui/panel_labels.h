#pragma once
// The Labels section (rendering model, "Labels"): automatic bone and table removal with progress
// and cancel; the label list (color, name, shown / hidden / own TF, voxel count); "show removed";
// the pick-and-grow tool (a click on the view labels the connected structure in an HU range, or
// gives a labelled piece back); undo and redo; save and load of the label volume.
#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "gui/panel_widgets.h"
#include "gui/workstation.h"

namespace angio {

// What a click on the view does while the tool is on.
enum class GrowTarget { label, unlabel };

struct LabelsPanelUi {
  bool growTool = false;  // clicks on the view pick and grow
  GrowTarget target = GrowTarget::label;
  int growLabel = 1;  // the label the grown voxels get
  double lowHu = 500, highHu = 3071;
  bool fillHoles = true;                 // marrow inside the grown cortex joins it
  std::string path = "labels.seg.nrrd";  // the save / load field
};

struct LabelsPanelInfo {
  bool hasVolume = false;
  std::array<std::uint64_t, 16> voxels{};  // per label, counted (0 until known)
  bool counted = false;
  bool busy = false;     // removal, growing or a label file in the works
  std::string busyWhat;  // e.g. "removing bone and table"
  double progress = 0;   // of the removal
  bool canUndo = false, canRedo = false;
  std::string undoWhat, redoWhat;
  std::string file;  // the label volume as loaded or saved
  std::string error;
};

struct LabelsPanelResult {
  std::optional<LabelStylesEdit> edit;
  bool removeBoneAndTable = false;
  bool cancel = false;
  bool undo = false, redo = false;
  bool save = false, load = false;  // ui.path
  bool browse = false;              // "...": the file browser fills ui.path
};

// The main TF's points recolored with the label's color: the label's own TF starts from what the
// user sees, in another hue.
std::vector<ControlPoint> tintedPoints(const std::vector<ControlPoint>& points, glm::vec3 color);

LabelsPanelResult drawLabelsPanel(const Document& document, LabelsPanelUi& ui,
                                  const LabelsPanelInfo& info, WidgetRects& rects);

}  // namespace angio
