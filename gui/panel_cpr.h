#pragma once
// The CPR section (thesis sec. 5.2.2): the CPR view beside the image, its mode, path and
// coloring, and the DVR+CPR hybrid in the image (thesis fig. 5.4) with its transition band. The
// hybrid shares the view's path and coloring.
#include <optional>
#include <string>

#include "gui/panel_widgets.h"
#include "gui/workstation.h"
#include "vessel/centerline.h"

namespace angio {

// What the section shows of the app's CPR and hybrid.
struct CprPanelInfo {
  const Centerlines* physical = nullptr;  // the loaded centerlines (the section needs them)
  bool vesselGlyphEnabled = false;
  std::string error;          // the CPR view's
  std::string hybridProblem;  // why the hybrid is not rendered although on
};

std::optional<CprEdit> drawCprPanel(const CprState& cpr, const CprPanelInfo& info, WidgetRects& rects);

// "all paths", or the path's index and name.
std::string cprPathLabel(const Centerlines& centerlines, int path);

}  // namespace angio
