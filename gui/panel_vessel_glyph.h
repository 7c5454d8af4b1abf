#pragma once
// The VesselGlyph section (thesis ch. 5): the centerline file field and its Load button, what was
// loaded, then (once there are centerlines) VesselGlyph on/off, the overlay, the focus and context
// shapes, the outside, cleft and half vessel, and the focus / context TF presets.
#include <optional>
#include <string>
#include <vector>

#include "gui/panel_widgets.h"
#include "gui/workstation.h"
#include "io/tf_file.h"
#include "vessel/centerline.h"

namespace angio {

struct VesselGlyphPanelUi {
  std::string path = "centerlines.csv";  // the centerline file field
};

// What the panel shows of the app's centerline loading.
struct VesselGlyphPanelInfo {
  bool loading = false;
  std::string loadingFile;                       // while loading
  const Centerlines* physical = nullptr;         // what was loaded (null: nothing)
  std::string file, warnings, error;             // where from, the loader's warnings, the last error
  std::string problem;                           // why VesselGlyph is not rendered although on
  const std::vector<Preset>* presets = nullptr;  // for the region TF combos
};

struct VesselGlyphPanelResult {
  std::optional<VesselGlyphEdit> edit;
  bool loadCenterlines = false;    // the Load button: load ui.path
  bool browseCenterlines = false;  // "...": the file browser chooses the file, then it loads
  std::string message;             // a preset that failed to load
};

// The points of all paths.
std::size_t centerlinePointCount(const Centerlines& centerlines);

VesselGlyphPanelResult drawVesselGlyphPanel(const VesselGlyphState& state, VesselGlyphPanelUi& ui,
                                            const VesselGlyphPanelInfo& info, WidgetRects& rects);

}  // namespace angio
