#include "gui/panel_view.h"

#include <iterator>

#include <imgui.h>

#include "gui/panel_widgets.h"

namespace angio {

namespace {

struct NamedView {
  const char* label;
  double angleDeg;
  const char* tooltip;
};
// About k (rendering model: theta = 0 looks along +P from the front; the viewer sits at -d).
constexpr NamedView kNamedViews[] = {
    {"AP", 0, "anterior view: looking from the front"},
    {"PA", 180, "posterior view: looking from the back"},
    {"L lat", 90, "left lateral: looking at the patient's left side"},
    {"R lat", 270, "right lateral: looking at the patient's right side"},
    {"LAO 45", 45, "left anterior oblique 45 deg"},
    {"RAO 45", 315, "right anterior oblique 45 deg"},
};

void drawAxisAndAngle(ViewState& view) {
  ImGui::TextUnformatted("axis");
  for (Axis axis : {Axis::i, Axis::j, Axis::k}) {
    ImGui::SameLine();
    if (ImGui::RadioButton(toString(axis), view.axis == axis)) view.axis = axis;
  }
  helpMarker("Rotation axis: k = the patient's long axis (default), i = left-right, j = front-back.");
  float angle = float(view.angleDeg);
  ImGui::SetNextItemWidth(-80);
  if (ImGui::SliderFloat("angle", &angle, 0, 360, "%.1f deg")) view.angleDeg = angle;
  helpMarker("Left-drag on the image turns the patient with the mouse; arrow keys +-1 deg (shift: 10).");
  for (std::size_t n = 0; n < std::size(kNamedViews); ++n) {
    if (n % 3) ImGui::SameLine();
    if (ImGui::Button(kNamedViews[n].label, ImVec2(90, 0))) view.angleDeg = kNamedViews[n].angleDeg;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("%s (%.0f deg)", kNamedViews[n].tooltip, kNamedViews[n].angleDeg);
  }
}

void drawMotion(ViewState& view, double fitZoom) {
  ImGui::Checkbox("auto-spin", &view.autoSpin);
  ImGui::SameLine();
  float spin = float(view.spinDegreesPerSecond);
  ImGui::SetNextItemWidth(130);
  if (ImGui::SliderFloat("deg/s", &spin, -180, 180, "%.0f", ImGuiSliderFlags_AlwaysClamp))
    view.spinDegreesPerSecond = spin;
  float perPixel = float(view.degreesPerPixel);
  ImGui::SetNextItemWidth(130);
  if (ImGui::SliderFloat("deg per pixel (drag)", &perPixel, 0.05f, 2.f, "%.2f",
                         ImGuiSliderFlags_AlwaysClamp))
    view.degreesPerPixel = perPixel;
  if (ImGui::Button("reset zoom/pan")) view.zoom = 1, view.panPx = glm::dvec2(0.0);
  ImGui::SameLine();
  if (ImGui::Button("fit view")) view.zoom = fitZoom, view.panPx = glm::dvec2(0.0);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Zoom so the volume as seen now fills the viewport; turning keeps the zoom");
  ImGui::SameLine();
  ImGui::TextDisabled("zoom %.2fx (wheel)", view.zoom);
  helpMarker(
      "Left drag turns, arrows +-1 deg (Shift +-10), wheel zooms, right or middle drag pans, a "
      "double-click resets zoom and pan. Shift+left drag adjusts instead of turning: DVR, the "
      "edited TF's HU shift (left/right) and opacity (up/down); MIP, window and level.");
}

}  // namespace

std::optional<ViewEdit> drawViewPanel(const ViewState& view, double fitZoom) {
  ViewState edited = view;
  drawAxisAndAngle(edited);
  drawMotion(edited, fitZoom);
  if (edited == view) return std::nullopt;
  return ViewEdit{edited};
}

}  // namespace angio
