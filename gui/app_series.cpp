// "Export rotation series" in the Export section of App: the settings, and the series rendered
// by exportRotationSeries (gui/series_export.h) in a BackgroundJob with progress and cancel.
#include <algorithm>
#include <cstdio>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "gui/app.h"
#include "gui/app_export.h"

namespace angio {

void App::drawSeriesExport() {
  const auto exportOpen = doc().panelsOpen.find("Export");
  if (exportOpen == doc().panelsOpen.end() || !exportOpen->second) return;
  SeriesSpec& spec = series_.spec;
  ImGui::Separator();
  ImGui::TextUnformatted("Rotation series (isd above, high-quality sampling)");
  ImGui::SetNextItemWidth(260);
  ImGui::InputText("folder##series", &series_.folder);
  noteRect("series_folder");
  ImGui::SetNextItemWidth(80);
  ImGui::InputDouble("start##series", &spec.startDeg, 0, 0, "%.1f");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  ImGui::InputDouble("arc deg##series", &spec.arcDeg, 0, 0, "%.1f");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  ImGui::InputInt("views##series", &spec.count, 0);
  noteRect("series_count");
  spec.arcDeg = std::clamp(spec.arcDeg, -360.0, 360.0);
  spec.count = std::clamp(spec.count, 1, 3600);
  const bool tiff = spec.format == "tif";
  if (ImGui::RadioButton("PNG", !tiff)) spec.format = "png";
  ImGui::SameLine();
  if (ImGui::RadioButton("TIFF 16-bit", tiff)) spec.format = "tif";
  ImGui::SameLine();
  ImGui::Checkbox("movie", &spec.movie);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Also write a movie through OpenCV: MP4 (mp4v), else AVI (MJPG)");
  if (spec.movie) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70);
    ImGui::InputDouble("fps", &spec.movieFps, 0, 0, "%.0f");
    spec.movieFps = std::clamp(spec.movieFps, 1.0, 120.0);
  }

  if (seriesJob_.running()) {
    char label[64];
    std::snprintf(label, sizeof label, "%.0f / %d views", seriesJob_.progress() * spec.count, spec.count);
    ImGui::ProgressBar(float(seriesJob_.progress()), ImVec2(260, 0), label);
    ImGui::SameLine();
    ImGui::BeginDisabled(seriesJob_.cancelRequested());
    if (ImGui::Button("Cancel##series")) seriesJob_.cancel();
    ImGui::EndDisabled();
    noteRect("series_cancel");
    return;
  }
  if (ImGui::Button("Export rotation series")) {
    seriesJob_.start([this, base = exportRecipe(), centerlines = exportCenterlines(), spec,
                      folder = series_.folder](JobControl& control) {
      SeriesCallbacks callbacks;
      callbacks.cancel = &control.cancel;
      callbacks.progress = [&control](int done, int total) { control.progress.store(double(done) / total); };
      return exportRotationSeries(data_.volume, centerlines, base, spec, folder, callbacks);
    });
    message_ = "exporting a rotation series to " + series_.folder;
  }
  noteRect("series_button");
  if (!series_.movieNote.empty()) ImGui::TextDisabled("last movie: %s", series_.movieNote.c_str());
}

}  // namespace angio
