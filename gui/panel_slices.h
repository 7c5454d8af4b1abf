#pragma once
// The Slices section: the linked slice view on and off, its window/level (fields and the reading
// room's presets) and the 3-D cursor the three slices go through, with a button back to the
// volume's centre. The slices themselves are drawn beside the image (gui/app_slices.cpp).
#include <optional>

#include <glm/glm.hpp>

#include "gui/panel_widgets.h"
#include "gui/workstation.h"

namespace angio {

// What the section shows of the cursor.
struct SlicesPanelInfo {
  glm::dvec3 cursorMm{0.0};  // where the slices are (the volume's centre until the user moves it)
  glm::ivec3 voxel{0};       // the cursor's voxel
  glm::ivec3 dims{0};        // the volume's
  double hu = 0;             // at that voxel
};

std::optional<SliceViewEdit> drawSlicesPanel(const SliceViewState& slices, const SlicesPanelInfo& info,
                                             WidgetRects& rects);

}  // namespace angio
