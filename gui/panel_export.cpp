#include "gui/panel_export.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "gui/message_row.h"

namespace angio {

namespace {

void drawSeriesAngles(SeriesSpec& spec, WidgetRects& rects) {
  ImGui::SetNextItemWidth(80);
  ImGui::InputDouble("start##series", &spec.startDeg, 0, 0, "%.1f");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  ImGui::InputDouble("arc deg##series", &spec.arcDeg, 0, 0, "%.1f");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  ImGui::InputInt("views##series", &spec.count, 0);
  noteRect(rects, "series_count");
  spec.arcDeg = std::clamp(spec.arcDeg, -360.0, 360.0);
  spec.count = std::clamp(spec.count, 1, 3600);
}

void drawSeriesFormat(SeriesSpec& spec) {
  const bool tiff = spec.format == "tif";
  if (ImGui::RadioButton("PNG", !tiff)) spec.format = "png";
  ImGui::SameLine();
  if (ImGui::RadioButton("TIFF 16-bit", tiff)) spec.format = "tif";
  ImGui::SameLine();
  ImGui::Checkbox("movie", &spec.movie);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Also write a movie through OpenCV: MP4 (mp4v), else AVI (MJPG)");
  if (!spec.movie) return;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(70);
  ImGui::InputDouble("fps", &spec.movieFps, 0, 0, "%.0f");
  spec.movieFps = std::clamp(spec.movieFps, 1.0, 120.0);
}

}  // namespace

ExportRequests drawImageExport(ExportPanelUi& ui, const JobInfo& job, WidgetRects& rects) {
  ExportRequests requests;
  ImGui::SetNextItemWidth(260);
  ImGui::InputText("file##export", &ui.path);
  noteRect(rects, "export_path");
  helpMarker(
      "Format by extension: .png (8-bit), .tif (16-bit), .exr (float RGBA). A JSON sidecar "
      "(FILE.json) records every parameter.");
  const double isdMin = 0.1, isdMax = 5;
  ImGui::SetNextItemWidth(120);
  ImGui::SliderScalar("isd", ImGuiDataType_Double, &ui.isd, &isdMin, &isdMax, "%.2f");
  helpMarker("Image sampling distance in voxel units: 0.5 = the high level, 0.25 for print.");
  if (job.running) {
    ImGui::Text("rendering ... %.0f s", job.seconds);
    ImGui::SameLine();
    requests.cancel = ImGui::SmallButton("cancel##export");
    return requests;
  }
  requests.start = ImGui::Button("Export image");
  noteRect(rects, "export_button");
  return requests;
}

ExportRequests drawSeriesExport(SeriesPanel& series, const JobInfo& job, WidgetRects& rects) {
  ExportRequests requests;
  ImGui::Separator();
  ImGui::TextUnformatted("Rotation series (isd above, high-quality sampling)");
  ImGui::SetNextItemWidth(260);
  ImGui::InputText("folder##series", &series.folder);
  noteRect(rects, "series_folder");
  drawSeriesAngles(series.spec, rects);
  drawSeriesFormat(series.spec);
  if (job.running) {
    char label[64];
    std::snprintf(label, sizeof label, "%.0f / %d views", job.progress * series.spec.count,
                  series.spec.count);
    ImGui::ProgressBar(float(job.progress), ImVec2(260, 0), label);
    ImGui::SameLine();
    ImGui::BeginDisabled(job.cancelRequested);
    requests.cancel = ImGui::Button("Cancel##series");
    ImGui::EndDisabled();
    noteRect(rects, "series_cancel");
    drawMessageRow({});  // the last movie's row
    return requests;
  }
  requests.start = ImGui::Button("Export rotation series");
  noteRect(rects, "series_button");
  drawMessageRow(
      {{MessageKind::note, series.movieNote.empty() ? "" : "last movie: " + series.movieNote}});
  return requests;
}

}  // namespace angio
