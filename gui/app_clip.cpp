// The crop box over the image: its twelve edges projected with the shown frame's view (follows
// zoom and pan), and a handle at each face's centre that a left drag moves along the face's axis
// (gui/crop_handles.h), as the crop widgets of Slicer and Horos do.
#include <imgui.h>

#include "gui/app.h"
#include "gui/crop_handles.h"

namespace angio {

namespace {

constexpr double kHandleGrabPx = 8;
constexpr float kHandleHalfPx = 4.f;
constexpr ImU32 kBoxColor = IM_COL32(255, 210, 60, 200);

glm::dvec2 asVec(ImVec2 p) { return {p.x, p.y}; }
ImVec2 asImVec(glm::dvec2 p) { return {float(p.x), float(p.y)}; }

}  // namespace

std::vector<CropHandle> App::shownCropHandles() const {
  if (!doc().clip.cropOn || !shown_ || !viewport_.hasImage) return {};
  return cropHandles(doc().clip.crop, [&](glm::dvec3 mm) { return asVec(dvrScreenOf(shownView_, mm)); });
}

void App::drawCropOverlay() {
  const bool leftHeld = ImGui::IsMouseDown(ImGuiMouseButton_Left);
  // Kept through the release frame, so the click handlers after this one know the gesture grabbed.
  if (cropGrab_ && !leftHeld && !ImGui::IsMouseReleased(ImGuiMouseButton_Left)) cropGrab_.reset();
  if (!doc().clip.cropOn || !shown_ || !viewport_.hasImage) return;
  const std::vector<CropHandle> handles = shownCropHandles();
  const glm::dvec2 pointer = asVec(ImGui::GetIO().MousePos);
  const std::optional<CropHandle> hovered =
      ImGui::IsItemHovered() ? handleAt(handles, pointer, kHandleGrabPx) : std::nullopt;
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !ImGui::GetIO().KeyShift)
    cropGrab_ = CropGrab{*hovered, doc().clip.crop, pointer};
  if (cropGrab_ && leftHeld) dragCropFace(pointer);
  if (hovered || cropGrab_) ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
  drawCropBox(handles, hovered);
}

// The grabbed face follows the pointer; the view does not turn meanwhile.
void App::dragCropFace(glm::dvec2 pointer) {
  viewport_.rotateDegrees = 0;
  ClipState clip = doc().clip;
  clip.crop = draggedCropBox(cropGrab_->start, cropGrab_->handle, pointer - cropGrab_->pointerAtGrab,
                             domainExtent(data_.volume));
  if (!(clip == doc().clip)) commit(ClipEdit{clip});
}

void App::drawCropBox(const std::vector<CropHandle>& handles, const std::optional<CropHandle>& hovered) {
  const CropBox& box = doc().clip.crop;
  // Corner n has bit `axis` set where it sits at the box's maximum along that axis.
  const auto corner = [&](int n) {
    glm::dvec3 p;
    for (int axis = 0; axis < 3; ++axis) p[axis] = (n >> axis) & 1 ? box.maxMm[axis] : box.minMm[axis];
    return dvrScreenOf(shownView_, p);
  };
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(viewport_.min, viewport_.max, true);
  for (int n = 0; n < 8; ++n)
    for (int axis = 0; axis < 3; ++axis)
      if (!((n >> axis) & 1))  // each edge once, from its corner at the minimum
        draw->AddLine(corner(n), corner(n | (1 << axis)), kBoxColor, 1.f);
  for (const CropHandle& handle : handles) {
    const bool active = (cropGrab_ && cropGrab_->handle.face == handle.face) ||
                        (!cropGrab_ && hovered && hovered->face == handle.face);
    const ImVec2 at = asImVec(handle.screen);
    const ImVec2 lo(at.x - kHandleHalfPx, at.y - kHandleHalfPx),
        hi(at.x + kHandleHalfPx, at.y + kHandleHalfPx);
    draw->AddRectFilled(lo, hi, active ? IM_COL32(255, 240, 160, 255) : IM_COL32(40, 30, 0, 200));
    draw->AddRect(lo, hi, kBoxColor);
  }
  draw->PopClipRect();
}

}  // namespace angio
