#include "gui/panel_rendering.h"

#include <iterator>

#include <imgui.h>

#include "gui/panel_widgets.h"

namespace angio {

namespace {

struct NamedWindow {
  const char* label;
  double window, level;
};
constexpr NamedWindow kMipWindows[] = {{"CTA", 800, 300}, {"bone", 1500, 500}, {"soft tissue", 400, 40}};

void drawMipWindow(RenderingEdit& edit) {
  float window = float(edit.mipWindow), level = float(edit.mipLevel);
  ImGui::SetNextItemWidth(200);
  if (ImGui::SliderFloat("window (HU)", &window, 1, 4000, "%.0f", ImGuiSliderFlags_AlwaysClamp))
    edit.mipWindow = window;
  ImGui::SetNextItemWidth(200);
  if (ImGui::SliderFloat("level (HU)", &level, -1024, 3071, "%.0f", ImGuiSliderFlags_AlwaysClamp))
    edit.mipLevel = level;
  for (std::size_t n = 0; n < std::size(kMipWindows); ++n) {
    if (n) ImGui::SameLine();
    if (ImGui::SmallButton(kMipWindows[n].label))
      edit.mipWindow = kMipWindows[n].window, edit.mipLevel = kMipWindows[n].level;
  }
}

void drawShading(Shading& shading) {
  ImGui::Checkbox("shading", &shading.enabled);
  if (!shading.enabled) return;
  float ka = float(shading.ka), kd = float(shading.kd);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  if (ImGui::SliderFloat("ka", &ka, 0, 1, "%.2f", ImGuiSliderFlags_AlwaysClamp)) shading.ka = ka;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  if (ImGui::SliderFloat("kd", &kd, 0, 1, "%.2f", ImGuiSliderFlags_AlwaysClamp)) shading.kd = kd;
}

// Seed 000's error-controlled adaptive integration, for every level, with its tolerance and first
// step. Experimental: it skips no empty space, so frames take seconds.
void drawAdaptive(std::optional<AdaptiveIntegration>& adaptive) {
  bool on = adaptive.has_value();
  ImGui::SameLine();  // beside pre-integration: the panels below keep their place
  if (ImGui::Checkbox("adaptive integration", &on))
    adaptive = on ? std::optional(AdaptiveIntegration{}) : std::nullopt;
  helpMarker(
      "Error-controlled adaptive integration along each ray (intervals bisected where the "
      "trapezoid and Simpson rules disagree) instead of samples every osd. An approximation, "
      "and slow: it skips no empty space. Nothing thicker than half the first step is missed.");
  if (!adaptive) return;
  float tolerance = float(adaptive->tolerance), step = float(adaptive->initialStep);
  ImGui::SetNextItemWidth(120);
  if (ImGui::SliderFloat("tolerance", &tolerance, 0.0001f, 0.1f, "%.4f",
                         ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
    adaptive->tolerance = tolerance;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  if (ImGui::SliderFloat("first step", &step, 0.5f, 8.f, "%.1f vx", ImGuiSliderFlags_AlwaysClamp))
    adaptive->initialStep = step;
}

}  // namespace

std::optional<RenderingEdit> drawRenderingPanel(const Document& document) {
  const RenderingEdit before{document.mode,
                             document.shading,
                             document.tf.mipWindow,
                             document.tf.mipLevel,
                             levelsPreintegrated(document),
                             document.levels[0].adaptive};
  RenderingEdit edit = before;
  bool mip = edit.mode == Compositing::mip;
  if (ImGui::Checkbox("MIP", &mip)) edit.mode = mip ? Compositing::mip : Compositing::dvr;
  helpMarker("Maximum intensity projection through a window/level instead of the transfer function.");
  if (mip) drawMipWindow(edit);
  else drawShading(edit.shading);
  if (!mip) {
    ImGui::Checkbox("pre-integrated", &edit.preintegrated);
    helpMarker(
        "Pre-integrated classification: each segment between two samples is coloured by the "
        "transfer function over all densities it passes, so thin or steep structures are "
        "not missed between samples. An approximation of the exact image; off is exact.");
    drawAdaptive(edit.adaptive);
  }
  if (edit == before) return std::nullopt;
  return edit;
}

}  // namespace angio
