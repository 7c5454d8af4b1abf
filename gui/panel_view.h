#pragma once
// The View section: rotation axis and angle, the named radiological views, auto-spin, drag speed,
// zoom/pan reset. Returns the edited view when a widget changed it.
#include <optional>

#include "gui/workstation.h"

namespace angio {

// `fitZoom`: the zoom of "fit view" (the current view filling the viewport, zoomToFitView).
std::optional<ViewEdit> drawViewPanel(const ViewState& view, double fitZoom = 1);

}  // namespace angio
