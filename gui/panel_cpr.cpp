#include "gui/panel_cpr.h"

#include <iterator>

#include <imgui.h>

#include "gui/message_row.h"

namespace angio {

namespace {

constexpr double kMaxTransitionMm = 10;
constexpr double kMinWindowHu = 1, kMaxWindowHu = 5000, kMinLevelHu = -1024, kMaxLevelHu = 3071;
constexpr CprMode kModes[] = {CprMode::straightened, CprMode::stretched, CprMode::projected};
constexpr const char* kColorings[] = {"CTA lumen", "calcium", "focus TF"};
constexpr const char* kColoringKeys[] = {"cta_lumen", "calcium", "focus_tf"};  // report layout names

// The grey window (also a right-drag in the pane) and the lateral width; the rows stay when they
// do not apply (greyed), so nothing moves under the pointer.
void drawWindowAndWidth(CprState& cpr, WidgetRects& rects) {
  ImGui::BeginDisabled(cpr.coloring == CprColoring::focusTf);
  ImGui::SetNextItemWidth(90);
  ImGui::DragScalar("window##cpr", ImGuiDataType_Double, &cpr.window.window, 4.f, &kMinWindowHu,
                    &kMaxWindowHu, "%.0f HU");
  noteRect(rects, "cpr_window");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  ImGui::DragScalar("level##cpr", ImGuiDataType_Double, &cpr.window.level, 4.f, &kMinLevelHu,
                    &kMaxLevelHu, "%.0f HU");
  noteRect(rects, "cpr_level");
  ImGui::EndDisabled();
  ImGui::BeginDisabled(cpr.mode == CprMode::projected);
  ImGui::SetNextItemWidth(150);
  ImGui::SliderScalar("width##cpr", ImGuiDataType_Double, &cpr.widthMm, &kMinCprWidthMm, &kMaxCprWidthMm,
                      "%.0f mm", ImGuiSliderFlags_AlwaysClamp);
  ImGui::EndDisabled();
  noteRect(rects, "cpr_width");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(cpr.mode == CprMode::projected ? "The projected CPR shows whole rows of the view"
                                                     : "Lateral extent of the CPR about the centerline");
}

void drawCprView(CprState& cpr, const Centerlines& centerlines, WidgetRects& rects) {
  ImGui::Checkbox("CPR view beside the image", &cpr.shown);
  noteRect(rects, "cpr_shown");
  for (std::size_t n = 0; n < std::size(kModes); ++n) {
    if (n) ImGui::SameLine();
    if (ImGui::RadioButton(toString(kModes[n]), cpr.mode == kModes[n])) cpr.mode = kModes[n];
    noteRect(rects, std::string("cpr_mode_") + toString(kModes[n]));
  }
  ImGui::SetNextItemWidth(220);
  if (ImGui::BeginCombo("path##cpr", cprPathLabel(centerlines, cpr.path).c_str())) {
    for (int n = -1; n < int(centerlines.paths.size()); ++n)
      if (ImGui::Selectable(cprPathLabel(centerlines, n).c_str(), cpr.path == n)) cpr.path = n;
    ImGui::EndCombo();
  }
  noteRect(rects, "cpr_path");
  ImGui::TextUnformatted("color");
  for (int n = 0; n < 3; ++n) {
    ImGui::SameLine();
    const CprColoring coloring = CprColoring(n);
    if (ImGui::RadioButton(kColorings[n], cpr.coloring == coloring)) {
      cpr.coloring = coloring;
      if (coloring == CprColoring::ctaLumen) cpr.window = kCtaLumenWindow;  // the presets
      if (coloring == CprColoring::calcium) cpr.window = kCalciumWindow;
    }
    noteRect(rects, std::string("cpr_colour_") + kColoringKeys[n]);
  }
  drawWindowAndWidth(cpr, rects);
}

void drawHybrid(CprState& cpr, bool hybridBefore, const CprPanelInfo& info, WidgetRects& rects) {
  ImGui::Separator();
  ImGui::Checkbox("DVR+CPR hybrid", &cpr.hybrid);
  // As it will be once this frame's edit is applied: turning the hybrid on turns VesselGlyph on.
  const bool vesselGlyphOn = info.vesselGlyphEnabled || (cpr.hybrid && !hybridBefore);
  noteRect(rects, "cpr_hybrid");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "The projected CPR of the path above, colored as above, in the VesselGlyph "
        "focus's footprint of the image (thesis fig. 5.4)");
  ImGui::SameLine();
  ImGui::BeginDisabled(!cpr.hybrid);  // there, greyed, while the hybrid is off: nothing moves
  ImGui::SetNextItemWidth(150);
  const double lo = 0, hi = kMaxTransitionMm;
  ImGui::SliderScalar("transition", ImGuiDataType_Double, &cpr.transitionMm, &lo, &hi, "%.1f mm",
                      ImGuiSliderFlags_AlwaysClamp);
  ImGui::EndDisabled();
  noteRect(rects, "cpr_transition");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Width of the band over which the CPR fades into the DVR (0: hard edge)");
  // The section's one message row: the CPR view's error, then the hybrid's.
  const bool waits = cpr.hybrid && !vesselGlyphOn;
  drawMessageRow(
      {{MessageKind::error, info.error},
       {MessageKind::error, cpr.hybrid ? info.hybridProblem : ""},
       {MessageKind::warning, waits ? "the hybrid needs VesselGlyph on (its focus is the cut)" : ""}});
}

}  // namespace

std::string cprPathLabel(const Centerlines& centerlines, int path) {
  if (path < 0 || path >= int(centerlines.paths.size())) return "all paths";
  const std::string& name = centerlines.paths[path].name;
  return std::to_string(path) + (name.empty() ? "" : ": " + name);
}

std::optional<CprEdit> drawCprPanel(const CprState& cpr, const CprPanelInfo& info, WidgetRects& rects) {
  if (!info.physical) return std::nullopt;
  CprState edited = cpr;
  drawCprView(edited, *info.physical, rects);
  drawHybrid(edited, cpr.hybrid, info, rects);
  if (edited == cpr) return std::nullopt;
  return CprEdit{edited};
}

}  // namespace angio
