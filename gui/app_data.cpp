// The Data section of App: open a volume file or DICOM folder (file browser, recent files,
// drag-and-drop, scripts), load it in the background with progress and cancel, replace the
// dataset on success, keep the previous one and show a dismissable error on failure; the
// dataset's dims, spacing, orientation and HU range.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>

#include <imgui.h>

#include "io/input_error.h"
#include "gui/app.h"
#include "gui/viewport.h"
#include "io/volume_reader.h"

namespace angio {

namespace fs = std::filesystem;

namespace {

LoadedDataset loadInBackground(const std::string& path, JobControl& control) {
  ReadOptions read;
  read.progress = [&control](double fraction) {
    control.progress.store(fraction);
    if (control.cancel.load()) throw LoadCancelled();
  };
  read.warn = printWarning;
  LoadedVolume loaded = readVolume(path, read);
  return LoadedDataset{std::move(loaded.volume), path, std::move(loaded.description)};
}

}  // namespace

void App::openDataset(const std::string& path) {
  if (path.empty()) return;
  if (load_.running()) {
    message_ = "still loading " + loadPath_ + "; cancel it first";
    return;
  }
  loadPath_ = absoluteDataset(path);  // a missing one stays as given: the load names it
  loadError_.clear();
  load_.start([path = loadPath_](JobControl& control) { return loadInBackground(path, control); });
  message_ = "loading " + loadPath_;
}

bool App::backgroundBusy() const { return load_.running() || seriesJob_.running() || vessel_.load.running(); }

void App::pollBackgroundJobs() {
  if (load_.ready()) {
    try {
      const double seconds = load_.seconds();
      replaceDataset(load_.take());
      char took[32];
      std::snprintf(took, sizeof took, " (%.2f s)", seconds);
      message_ = "opened " + loadPath_ + took;
    } catch (const LoadCancelled&) {
      message_ = "loading " + loadPath_ + " cancelled";
    } catch (const std::exception& error) {
      loadError_ = error.what();
      message_.clear();
    }
  }
  pollCenterlineLoad();  // after the dataset: centerlines are checked against the one shown
  if (seriesJob_.ready()) {
    try {
      const SeriesResult result = seriesJob_.take();
      message_ = result.summary;
      series_.movieNote = result.movieNote;
    } catch (const std::exception& error) {
      message_ = error.what();
    }
  }
}

// The renderer, the histogram job and the exports read the volume: all stop before it goes.
void App::replaceDataset(LoadedDataset dataset) {
  seriesJob_.stop();
  if (export_.cancel) export_.cancel->store(true);
  if (export_.job.valid()) export_.job.wait();
  export_.job = {};
  if (histogramJob_.valid()) histogramJob_.wait();
  histogramJob_ = {};
  renderer_.reset();
  shown_.reset();
  incoming_.reset();
  lastRequest_.reset();
  requestTimes_.clear();
  latency_.restart();
  data_ = std::move(dataset);
  commit(DatasetOpened{data_.name});
  histogram_.clear();
  huRange_.reset();
  renderer_ = std::make_unique<ProgressiveRenderer>(data_.volume, ProgressiveCallbacks{{}, wakeUi_});
  histogramJob_ = std::async(std::launch::async, [this] { return densityHistogram(data_.volume); });
}

void App::drawDataSection() {
  drawSessionBanner();
  if (const auto chosen = drawFileBrowser(browser_)) openDataset(chosen->string());
  if (!sectionHeader("Data")) return;
  if (ImGui::Button("Open...")) {
    const fs::path current = loadPath_.empty() ? fs::path(data_.name) : fs::path(loadPath_);
    std::error_code error;
    browser_.show(fs::is_directory(current.parent_path(), error) ? current.parent_path() : fs::current_path());
  }
  noteRect("data_open");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(200);
  if (ImGui::BeginCombo("##recent", "recent files")) {
    for (const std::string& file : doc().recentFiles)
      if (ImGui::Selectable(file.c_str())) openDataset(file);
    if (doc().recentFiles.empty()) ImGui::TextDisabled("(none yet)");
    ImGui::EndCombo();
  }
  if (load_.running()) {
    char label[64];
    std::snprintf(label, sizeof label, "loading %.0f%% (%.0f s)", 100 * load_.progress(), load_.seconds());
    ImGui::ProgressBar(float(load_.progress()), ImVec2(260, 0), label);
    ImGui::SameLine();
    ImGui::BeginDisabled(load_.cancelRequested());
    if (ImGui::Button("Cancel##load")) load_.cancel();
    ImGui::EndDisabled();
    ImGui::TextDisabled("%s", loadPath_.c_str());
  }
  if (!loadError_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.45f, 0.35f, 1));
    ImGui::TextWrapped("could not open: %s", loadError_.c_str());
    ImGui::PopStyleColor();
    if (ImGui::SmallButton("Dismiss##loaderror")) loadError_.clear();
    noteRect("data_dismiss");
  }

  const Volume& v = data_.volume;
  ImGui::TextWrapped("%s", data_.name.c_str());
  if (!data_.description.empty()) ImGui::TextDisabled("%s", data_.description.c_str());
  ImGui::Text("%d x %d x %d voxels, %.3g x %.3g x %.3g mm", v.dims.x, v.dims.y, v.dims.z,
              v.spacing.x, v.spacing.y, v.spacing.z);
  ImGui::Text("axes i j k -> %c %c %c, origin %.1f %.1f %.1f mm (LPS)", lpsLetter(v.direction[0]),
              lpsLetter(v.direction[1]), lpsLetter(v.direction[2]), v.origin.x, v.origin.y, v.origin.z);
  if (ImGui::IsItemHovered()) {
    const glm::dmat3& d = v.direction;
    ImGui::SetTooltip("direction (columns = i, j, k in LPS):\n%6.3f %6.3f %6.3f\n%6.3f %6.3f %6.3f\n%6.3f %6.3f %6.3f",
                      d[0].x, d[1].x, d[2].x, d[0].y, d[1].y, d[2].y, d[0].z, d[1].z, d[2].z);
  }
  if (huRange_)
    ImGui::Text("HU %.0f .. %.0f", huOfDensity(huRange_->minDensity), huOfDensity(huRange_->maxDensity));
  else
    ImGui::TextDisabled("HU range: counting...");
}

nlohmann::json App::dataReport() const {
  const Volume& v = data_.volume;
  nlohmann::json hu = nullptr;
  if (huRange_) hu = {huOfDensity(huRange_->minDensity), huOfDensity(huRange_->maxDensity)};
  return {{"name", data_.name},
          {"description", data_.description},
          {"dims", {v.dims.x, v.dims.y, v.dims.z}},
          {"spacing", {v.spacing.x, v.spacing.y, v.spacing.z}},
          {"orientation", std::string{lpsLetter(v.direction[0]), lpsLetter(v.direction[1]), lpsLetter(v.direction[2])}},
          {"hu_range", hu},
          {"loading", load_.running()},
          {"load_error", loadError_},
          {"recent_files", doc().recentFiles},
          {"panels_open", doc().panelsOpen},
          {"session_offered", offeredSession_ ? offeredSession_->dataset : ""},
          {"series_running", seriesJob_.running()},
          {"movie_note", series_.movieNote}};
}

}  // namespace angio
