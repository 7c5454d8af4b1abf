#include "gui/panel_status.h"

#include <cstdio>

#include <imgui.h>

namespace angio {

void drawStatusBar(const StatusInfo& info, float height) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - height));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, height));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8, 5));
  ImGui::Begin("##status", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
  ImGui::PopStyleVar();
  if (info.shownLevel) {
    ImGui::Text("shown: %s", toString(*info.shownLevel));
  } else {
    ImGui::TextUnformatted("shown: -");
  }
  for (int q = 0; q < kQualityLevels; ++q) {
    ImGui::SameLine(0, 14);
    const LevelTiming& t = info.status.levels[q];
    if (t.done) ImGui::Text("%s %.0f ms", toString(Quality(q)), t.ms);
    else ImGui::TextDisabled("%s -", toString(Quality(q)));
  }
  ImGui::SameLine(0, 14);
  if (info.status.rendering) {
    char label[48];
    std::snprintf(label, sizeof label, "%s %.0f ms", toString(*info.status.rendering),
                  info.status.renderingMs);
    ImGui::ProgressBar(float(info.status.estimatedProgress()), ImVec2(150, 0), label);
  } else if (info.status.preparing && info.status.tilesBuilt > 0) {
    // The slice tiles of a new rotation axis: 1-2 s at 512x512x1200 about i or j.
    char label[48];
    std::snprintf(label, sizeof label, "tiles about %s", toString(*info.status.preparing));
    ImGui::ProgressBar(float(info.status.tilesBuilt), ImVec2(150, 0), label);
  } else {
    ImGui::ProgressBar(info.status.busy ? 0.f : 1.f, ImVec2(150, 0),
                       info.status.busy ? "preparing" : "done");
  }
  double samplesPerSecond = 0;
  for (const LevelTiming& t : info.status.levels)
    if (t.done) samplesPerSecond = t.samplesPerSecond();
  ImGui::SameLine(0, 14);
  ImGui::Text("%.0f Msamples/s", samplesPerSecond * 1e-6);
  ImGui::SameLine(0, 14);
  ImGui::Text("UI %.1f ms", info.uiFrameMs);
  if (!info.message.empty() || !info.status.error.empty()) {
    ImGui::SameLine(0, 14);
    ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "%s",
                       info.status.error.empty() ? info.message.c_str() : info.status.error.c_str());
  }
  ImGui::End();
}

}  // namespace angio
