#include "gui/panel_slices.h"

#include <string>

#include <imgui.h>

#include "gui/slice_pane.h"

namespace angio {

namespace {

constexpr float kFieldWidth = 110;

void drawWindowLevel(WindowLevel& windowLevel, WidgetRects& rects) {
  const double minWindow = 1, maxWindow = 1e4, minLevel = -2000, maxLevel = 1e4;
  ImGui::SetNextItemWidth(kFieldWidth);
  ImGui::DragScalar("window##slices", ImGuiDataType_Double, &windowLevel.window, 2.f, &minWindow,
                    &maxWindow, "%.0f HU", ImGuiSliderFlags_AlwaysClamp);
  noteRect(rects, "slices_window");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(kFieldWidth);
  ImGui::DragScalar("level##slices", ImGuiDataType_Double, &windowLevel.level, 2.f, &minLevel, &maxLevel,
                    "%.0f HU", ImGuiSliderFlags_AlwaysClamp);
  noteRect(rects, "slices_level");
  helpMarker("Right-drag in a slice: sideways the window, up and down the level.");
  for (const WindowLevelPreset& preset : kWindowLevelPresets) {
    if (&preset != &kWindowLevelPresets.front()) ImGui::SameLine();
    if (ImGui::Button((std::string(preset.name) + "##slices").c_str())) windowLevel = preset.windowLevel;
    noteRect(rects, std::string("slices_preset_") + preset.name);
  }
}

void drawCursor(SliceViewState& slices, const SlicesPanelInfo& info, WidgetRects& rects) {
  ImGui::Text("cursor  i %d/%d  j %d/%d  k %d/%d   %.0f HU", info.voxel.x, info.dims.x - 1, info.voxel.y,
              info.dims.y - 1, info.voxel.z, info.dims.z - 1, info.hu);
  ImGui::Text("        %.1f, %.1f, %.1f mm", info.cursorMm.x, info.cursorMm.y, info.cursorMm.z);
  ImGui::SameLine();
  ImGui::BeginDisabled(!slices.cursorMm);
  if (ImGui::SmallButton("centre##slices")) slices.cursorMm.reset();
  noteRect(rects, "slices_centre");
  ImGui::EndDisabled();
}

}  // namespace

std::optional<SliceViewEdit> drawSlicesPanel(const SliceViewState& slices, const SlicesPanelInfo& info,
                                             WidgetRects& rects) {
  SliceViewState edited = slices;
  ImGui::Checkbox("axial, coronal, sagittal beside the image", &edited.shown);
  noteRect(rects, "slices_shown");
  helpMarker(
      "Slices through the 3-D cursor. Click or drag in a slice to move the cursor there, the wheel "
      "steps through slices (Shift: 10), a click on the image puts the cursor on the surface "
      "under it.");
  drawWindowLevel(edited.windowLevel, rects);
  drawCursor(edited, info, rects);
  if (edited == slices) return std::nullopt;
  return SliceViewEdit{edited};
}

}  // namespace angio
