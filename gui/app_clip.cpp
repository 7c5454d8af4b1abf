// The crop box over the image: its twelve edges projected with the shown frame's view (follows
// zoom and pan), so the user sees where the six planes are while dragging their sliders.
#include <imgui.h>

#include "gui/app.h"

namespace angio {

void App::drawCropOverlay() {
  if (!doc().clip.cropOn || !shown_ || !viewport_.hasImage) return;
  const ViewGeometry& view = shownView_;
  const CropBox& box = doc().clip.crop;
  // Corner n has bit `axis` set where it sits at the box's maximum along that axis.
  const auto corner = [&](int n) {
    glm::dvec3 p;
    for (int axis = 0; axis < 3; ++axis) p[axis] = (n >> axis) & 1 ? box.maxMm[axis] : box.minMm[axis];
    return dvrScreenOf(view, p);
  };
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(viewport_.min, viewport_.max, true);
  for (int n = 0; n < 8; ++n)
    for (int axis = 0; axis < 3; ++axis)
      if (!((n >> axis) & 1))  // each edge once, from its corner at the minimum
        draw->AddLine(corner(n), corner(n | (1 << axis)), IM_COL32(255, 210, 60, 200), 1.f);
  draw->PopClipRect();
}

}  // namespace angio
