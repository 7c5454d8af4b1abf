#pragma once
// The Crop & clip section (rendering model, "Crop, clip, slab"): a crop box along the voxel axes
// (six sliders, mm of the volume frame), one clip plane (facing the viewer, or fixed in the volume
// across a voxel axis, the view's direction or any azimuth and elevation, at an offset from the
// volume centre) and a thick slab facing the viewer (offset, thickness),
// each switched on and off; Reset switches everything off. Returns the edit when a widget changed
// the settings.
#include <optional>

#include <glm/glm.hpp>

#include "gui/panel_widgets.h"
#include "gui/workstation.h"

namespace angio {

// `extentMm`: the shown volume's domain extent (the sliders' ranges); `towardsViewer`: the view's
// direction towards the viewer in the volume frame (Fix and From view).
std::optional<ClipEdit> drawClipPanel(const ClipState& clip, glm::dvec3 extentMm,
                                      glm::dvec3 towardsViewer, WidgetRects& rects);

}  // namespace angio
