#include "gui/panel_rendering.h"

#include <algorithm>
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

// Seed 000's error-controlled adaptive integration: its tolerance and first step.
void drawAdaptiveIntegration(AdaptiveIntegration& adaptive) {
  float tolerance = float(adaptive.tolerance), step = float(adaptive.initialStep);
  ImGui::SetNextItemWidth(120);
  if (ImGui::SliderFloat("tolerance", &tolerance, 0.0001f, 0.1f, "%.4f",
                         ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
    adaptive.tolerance = tolerance;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  if (ImGui::SliderFloat("first step", &step, 0.5f, 8.f, "%.1f vx", ImGuiSliderFlags_AlwaysClamp))
    adaptive.initialStep = step;
}

// Seed 003's adaptive sampling in three dimensions: the image pyramid's levels and the oracle's
// tolerance.
void drawAdaptiveSampling(AdaptiveSampling& adaptive) {
  ImGui::SetNextItemWidth(90);
  if (ImGui::SliderInt("levels", &adaptive.levels, 0, 5, "%d", ImGuiSliderFlags_AlwaysClamp))
    adaptive.rayLevels = std::max(adaptive.rayLevels, adaptive.levels);
  ImGui::SameLine();
  float tolerance = float(adaptive.tolerance);
  ImGui::SetNextItemWidth(120);
  if (ImGui::SliderFloat("oracle tolerance", &tolerance, 0.001f, 1.f, "%.3f",
                         ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
    adaptive.tolerance = tolerance;
}

// Where the rays are sampled, for every level: every osd (exact), or one of the seeds' adaptive
// schemes, whose settings take the next row. A choice of one, beside pre-integration, so the
// panels below keep their place.
void drawAlongRays(RenderingEdit& edit) {
  const char* const kinds[] = {"every sample", "adaptive integration", "adaptive sampling"};
  int kind = edit.adaptive ? 1 : edit.adaptiveSampling ? 2 : 0;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(170);
  if (ImGui::Combo("##along rays", &kind, kinds, IM_ARRAYSIZE(kinds))) {
    edit.adaptive = kind == 1 ? std::optional(AdaptiveIntegration{}) : std::nullopt;
    edit.adaptiveSampling = kind == 2 ? std::optional(AdaptiveSampling{}) : std::nullopt;
  }
  helpMarker(
      "Every sample: the exact image. Adaptive integration (seed 000): intervals bisected where "
      "the trapezoid and Simpson rules disagree; slow, it skips no empty space; nothing thicker "
      "than half the first step is missed. Adaptive sampling (seed 003): where the transfer "
      "function is smooth around a point, samples along rays are skipped and rays across the "
      "image synthesised from coarser ones, segments pre-integrated; slower than every sample "
      "on our scans. Both are approximations.");
  if (edit.adaptive) drawAdaptiveIntegration(*edit.adaptive);
  if (edit.adaptiveSampling) drawAdaptiveSampling(*edit.adaptiveSampling);
}

}  // namespace

std::optional<RenderingEdit> drawRenderingPanel(const Document& document) {
  const RenderingEdit before{document.mode,
                             document.shading,
                             document.tf.mipWindow,
                             document.tf.mipLevel,
                             levelsPreintegrated(document),
                             document.levels[0].adaptive,
                             document.levels[0].adaptiveSampling};
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
    drawAlongRays(edit);
  }
  if (edit == before) return std::nullopt;
  return edit;
}

}  // namespace angio
