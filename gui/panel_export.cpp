#include "gui/panel_export.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>

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
    ImGui::SetTooltip(
        "Also write a movie through OpenCV: MP4 (H.264), else MP4 (mp4v), else AVI (MJPG)");
  if (!spec.movie) return;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(70);
  ImGui::InputDouble("fps", &spec.movieFps, 0, 0, "%.0f");
  spec.movieFps = std::clamp(spec.movieFps, 1.0, 120.0);
}

// The start button, or in its place (same row) the question whether to overwrite what is there:
// a click on the button asks first when `overwrites()` (asked on the click only: it looks at the
// disk); `confirming` holds what was asked about.
bool drawStartOrConfirm(const char* label, const char* name, const std::string& target,
                        const std::function<bool()>& overwrites, std::string& confirming,
                        WidgetRects& rects) {
  if (!confirming.empty() && confirming != target) confirming.clear();  // the field changed
  if (confirming.empty()) {
    const bool clicked = ImGui::Button(label);
    noteRect(rects, name);
    if (!clicked) return false;
    if (!overwrites()) return true;
    confirming = target;
    return false;
  }
  ImGui::TextColored(ImVec4(1, 0.8f, 0.4f, 1), "replace what is there?");
  ImGui::SameLine();
  const bool replace = ImGui::Button((std::string("Overwrite##") + name).c_str());
  noteRect(rects, std::string(name) + "_overwrite");
  ImGui::SameLine();
  const bool keep = ImGui::Button((std::string("Keep##") + name).c_str());
  noteRect(rects, std::string(name) + "_keep");
  if (replace || keep) confirming.clear();
  return replace;
}

bool exists(const std::filesystem::path& path) {
  std::error_code error;
  return std::filesystem::exists(path, error);
}

}  // namespace

bool exportWouldOverwrite(const std::string& path) {
  return !path.empty() && (exists(path) || exists(path + ".json"));
}

bool seriesWouldOverwrite(const std::string& folder, const std::string& prefix) {
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end;
       it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix + "-", 0) == 0 || name == prefix + ".mp4" || name == prefix + ".avi")
      return true;
  }
  return false;
}

ExportRequests drawImageExport(ExportPanelUi& ui, const JobInfo& job, WidgetRects& rects) {
  ExportRequests requests;
  ImGui::SetNextItemWidth(230);
  ImGui::InputText("##exportfile", &ui.path);
  noteRect(rects, "export_path");
  requests.browse = drawBrowseButton("export", rects);
  ImGui::SameLine();
  ImGui::TextUnformatted("file");
  helpMarker(
      "Format by extension: .png (8-bit), .tif (16-bit), .exr (float RGBA). A JSON sidecar "
      "(FILE.json) records every parameter.");
  const double isdMin = 0.1, isdMax = 5;
  ImGui::SetNextItemWidth(120);
  ImGui::SliderScalar("isd", ImGuiDataType_Double, &ui.isd, &isdMin, &isdMax, "%.2f",
                      ImGuiSliderFlags_AlwaysClamp);
  helpMarker("Image sampling distance in voxel units: 0.5 = the high level, 0.25 for print.");
  if (job.running) {
    ImGui::Text("rendering ... %.0f s", job.seconds);
    ImGui::SameLine();
    requests.cancel = ImGui::SmallButton("cancel##export");
    return requests;
  }
  requests.start = drawStartOrConfirm(
      "Export image", "export_button", ui.path, [&] { return exportWouldOverwrite(ui.path); },
      ui.confirmingPath, rects);
  return requests;
}

ExportRequests drawSeriesExport(SeriesPanel& series, const JobInfo& job, WidgetRects& rects) {
  ExportRequests requests;
  ImGui::Separator();
  ImGui::TextUnformatted("Rotation series (isd above, high-quality sampling)");
  ImGui::SetNextItemWidth(230);
  ImGui::InputText("##seriesfolder", &series.folder);
  noteRect(rects, "series_folder");
  requests.browse = drawBrowseButton("series", rects);
  ImGui::SameLine();
  ImGui::TextUnformatted("folder");
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
  requests.start = drawStartOrConfirm(
      "Export rotation series", "series_button", series.folder,
      [&] { return seriesWouldOverwrite(series.folder, series.spec.prefix); }, series.confirmingFolder,
      rects);
  drawMessageRow(
      {{MessageKind::note, series.movieNote.empty() ? "" : "last movie: " + series.movieNote}});
  return requests;
}

}  // namespace angio
