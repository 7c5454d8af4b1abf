// Clicks on the image in App: a left press released within kClickSlopPx of where it went down is
// a click (more is a drag, which turns the view); its image point, and the visible point under it
// as the renderer sees it (core/ray_pick.h: DVR's opacity 0.5, MIP's maximum). The tools that act
// on a click (pick and grow, tracing) start from here.
#include <imgui.h>

#include "core/label_tables.h"
#include "core/view_geometry.h"
#include "gui/app.h"

namespace angio {

namespace {

constexpr float kClickSlopPx = 3;  // a left press that moved less than this is a click, not a drag

}  // namespace

std::optional<glm::dvec2> App::clickedImagePoint() const {
  if (!shown_ || !viewport_.hasImage || cropGrab_) return std::nullopt;  // a handle's, not a click
  if (!ImGui::IsItemHovered() || !ImGui::IsMouseReleased(ImGuiMouseButton_Left)) return std::nullopt;
  const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.f);
  if (drag.x * drag.x + drag.y * drag.y > kClickSlopPx * kClickSlopPx) return std::nullopt;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const ViewGeometry& view = shownView_;
  return glm::dvec2{
      (mouse.x - viewport_.imageMin.x) / (viewport_.imageMax.x - viewport_.imageMin.x) * view.width,
      (mouse.y - viewport_.imageMin.y) / (viewport_.imageMax.y - viewport_.imageMin.y) * view.height};
}

std::optional<PickedPoint> App::pickVisible(glm::dvec2 imagePoint) const {
  const TransferFunction tf = renderedTf(doc());
  const TfTable table = buildTable(tf);
  const LabelTables labels(tf.labels);
  return pickPoint(data_.volume, {nullptr, nullptr, nullptr, &table, &labels}, shown_->params,
                   imagePoint);
}

std::optional<glm::vec2> App::screenOfPhysical(const glm::dvec3& physicalMm) const {
  if (!shown_ || !viewport_.hasImage) return std::nullopt;
  const ViewGeometry& view = shownView_;
  const ImVec2 at = dvrScreenOf(view, volumeFrameMm(data_.volume, physicalMm));
  return glm::vec2(at.x, at.y);
}

}  // namespace angio
