// The DVR+CPR hybrid in App (issue 6 item 5; thesis sec. 5.2.2, fig. 5.4 and 5.5): a checkbox and
// the transition band in the CPR section, which also picks the hybrid's path and colouring (the
// CPR view's), and the finish step the progressive renderer runs on every level's VesselGlyph
// image (core/progressive_renderer.h RegionSource::finish): the projected CPR composited into
// the focus footprint in the level's own view, so each level shows the hybrid, aligned to the
// pixel, and the UI thread only uploads it.
#include <cstdio>
#include <exception>
#include <memory>

#include <imgui.h>

#include "gui/app.h"
#include "render/hybrid_cpr_step.h"

namespace angio {

namespace {

constexpr double kMaxTransitionMm = 10;
constexpr const char* kColouringNames[] = {"cta-lumen", "calcium", "focus-tf"};

}  // namespace

void App::drawHybridControls() {
  SessionCpr& cpr = state_.cpr;
  ImGui::Separator();
  if (ImGui::Checkbox("DVR+CPR hybrid", &cpr.hybrid) && cpr.hybrid) state_.vesselGlyph.enabled = true;
  noteRect("cpr_hybrid");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The projected CPR of the path above, coloured as above, in the VesselGlyph "
                      "focus's footprint of the image (thesis fig. 5.4)");
  if (!cpr.hybrid) return;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(150);
  const double lo = 0, hi = kMaxTransitionMm;
  ImGui::SliderScalar("transition", ImGuiDataType_Double, &cpr.transitionMm, &lo, &hi, "%.1f mm");
  noteRect("cpr_transition");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Width of the band over which the CPR fades into the DVR (0: hard edge)");
  if (!state_.vesselGlyph.enabled)
    ImGui::TextColored(ImVec4(1, 0.8f, 0.4f, 1), "the hybrid needs VesselGlyph on (its focus is the cut)");
  if (!vessel_.hybridProblem.empty())
    ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", vessel_.hybridProblem.c_str());
}

nlohmann::json App::hybridReport() const {
  const SessionCpr& cpr = state_.cpr;
  return {{"enabled", cpr.hybrid},
          {"rendering", scene_ && scene_->recipe().hybrid.has_value()},
          {"path", cpr.path},
          {"transition_mm", cpr.transitionMm},
          {"colouring", kColouringNames[int(cpr.colouring)]},
          {"problem", vessel_.hybridProblem}};
}

}  // namespace angio
