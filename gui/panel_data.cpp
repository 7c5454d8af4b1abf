#include "gui/panel_data.h"

#include <cstdio>

#include <imgui.h>

#include "core/voxel.h"
#include "gui/message_row.h"
#include "gui/study_banner.h"
#include "gui/viewport.h"

namespace angio {

namespace {

// One row whatever happens (the dataset's lines below stay put): the load's bar and Cancel while
// loading, a failed load's error and Dismiss, else empty.
void drawLoad(const DataPanelInfo& info, DataPanelRequests& requests, WidgetRects& rects) {
  if (info.loading) {
    char label[64];
    std::snprintf(label, sizeof label, "loading %.0f%% (%.0f s)", 100 * info.loadProgress,
                  info.loadSeconds);
    ImGui::ProgressBar(float(info.loadProgress), ImVec2(260, 0), label);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", info.loadPath.c_str());
    ImGui::SameLine();
    ImGui::BeginDisabled(info.cancelRequested);
    if (ImGui::Button("Cancel##load")) requests.cancelLoad = true;
    ImGui::EndDisabled();
    return;
  }
  if (info.loadError.empty()) {
    drawBlankWidgetRows(1);
    return;
  }
  if (ImGui::Button("Dismiss##loaderror")) requests.dismissError = true;
  noteRect(rects, "data_dismiss");
  ImGui::SameLine();
  drawMessageRow({{MessageKind::error, "could not open: " + info.loadError}});
}

void drawDataset(const DataPanelInfo& info) {
  ImGui::TextWrapped("%s", info.name.c_str());
  if (!info.description.empty()) ImGui::TextDisabled("%s", info.description.c_str());
  for (const std::string& line : studyBanner(info.study)) ImGui::TextUnformatted(line.c_str());
  if (info.volume) {
    const Volume& v = *info.volume;
    ImGui::Text("%d x %d x %d voxels, %.3g x %.3g x %.3g mm", v.dims.x, v.dims.y, v.dims.z, v.spacing.x,
                v.spacing.y, v.spacing.z);
    ImGui::Text("axes i j k -> %c %c %c, origin %.1f %.1f %.1f mm (LPS)", lpsLetter(v.direction[0]),
                lpsLetter(v.direction[1]), lpsLetter(v.direction[2]), v.origin.x, v.origin.y,
                v.origin.z);
    if (ImGui::IsItemHovered()) {
      const glm::dmat3& d = v.direction;
      ImGui::SetTooltip(
          "direction (columns = i, j, k in LPS):\n%6.3f %6.3f %6.3f\n%6.3f %6.3f %6.3f\n%6.3f %6.3f "
          "%6.3f",
          d[0].x, d[1].x, d[2].x, d[0].y, d[1].y, d[2].y, d[0].z, d[1].z, d[2].z);
    }
  }
  if (info.densities) {
    ImGui::Text("HU %.0f .. %.0f", huOfDensity(info.densities->minDensity),
                huOfDensity(info.densities->maxDensity));
    if (!info.huCalibrated) {  // on the same row: rows do not come and go under the pointer
      ImGui::SameLine();
      ImGui::TextColored(ImVec4(1.f, 0.75f, 0.3f, 1.f), "not calibrated HU?");
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Almost no voxels below -500 HU (air): the values may not be Hounsfield units.\n"
            "The TF presets and window/level presets assume HU; fit a TF to the histogram.");
    }
  } else ImGui::TextDisabled("HU range: counting...");
}

}  // namespace

DataPanelRequests drawDataPanel(const Document& document, const DataPanelInfo& info,
                                WidgetRects& rects) {
  DataPanelRequests requests;
  requests.browse = ImGui::Button("Open...");
  noteRect(rects, "data_open");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(200);
  if (ImGui::BeginCombo("##recent", "recent files")) {
    for (const std::string& file : document.recentFiles)
      if (ImGui::Selectable(file.c_str())) requests.open = file;
    if (document.recentFiles.empty()) ImGui::TextDisabled("(none yet)");
    ImGui::EndCombo();
  }
  drawLoad(info, requests, rects);
  drawDataset(info);
  return requests;
}

}  // namespace angio
