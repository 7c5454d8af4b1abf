// The side panel of App (its sections in order; the Export section's image export) and the status bar.
#include <algorithm>
#include <cstdio>
#include <exception>

#include <imgui.h>

#include "gui/app.h"
#include "gui/app_export.h"
#include "gui/panel_clip.h"
#include "gui/panel_export.h"
#include "gui/panel_rendering.h"
#include "gui/panel_status.h"
#include "gui/panel_view.h"
#include "render/export.h"

namespace angio {

void App::drawSidePanel() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(std::max(io.DisplaySize.x - kPanelWidth, 64.f), 0));
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, std::max(io.DisplaySize.y - kStatusHeight, 64.f)));
  ImGui::Begin("##panel", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
  drawDataSection();
  if (sectionHeader("View")) commit(drawViewPanel(doc().view, fitViewZoom()));
  drawTfSection();
  drawVesselSection();
  drawCprSection();
  drawVesselsSection();
  drawLabelsSection();
  if (sectionHeader("Rendering")) commit(drawRenderingPanel(doc()));
  drawSlicesSection();
  if (sectionHeader("Crop & clip", false))
    commit(drawClipPanel(doc().clip, domainExtent(data_.volume), -shownView_.viewDir, widgetRects_));
  drawExportSection();
  drawSeriesExport();  // part of the Export section
  drawSessionSection();
  ImGui::End();
}

void App::drawExportSection() {
  if (!sectionHeader("Export")) return;
  JobInfo job;
  job.running = export_.job.valid();
  job.seconds = std::chrono::duration<double>(Clock::now() - export_.started).count();
  const ExportRequests requests = drawImageExport(export_.ui, job, widgetRects_);
  if (requests.cancel) export_.cancel->store(true);
  if (requests.browse) browseFor(BrowserPurpose::exportImage, export_.ui.path);
  if (!requests.start) return;
  export_.cancel = std::make_shared<std::atomic<bool>>(false);
  export_.started = Clock::now();
  export_.job = std::async(
      std::launch::async,
      [this, recipe = exportRecipe(), centerlines = exportCenterlines(), path = export_.ui.path,
       cancel = export_.cancel, labels = unsavedLabels(), traced = unsavedCenterlines()]() mutable {
        if (labels) saveLabelsFor(recipe, data_.volume, *labels, path + ".labels.seg.nrrd");
        if (traced)
          centerlines = saveCenterlinesFor(recipe, data_.volume, *traced, path + kBesideCenterlines);
        return exportView(data_.volume, centerlines, recipe, path, cancel.get());
      });
  message_ = "exporting " + export_.ui.path;
}

void App::pollExport() {
  if (!export_.job.valid() || export_.job.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return;
  try {
    const std::string summary = export_.job.get();
    message_ = summary.empty() ? "export cancelled" : summary;
  } catch (const std::exception& error) {
    message_ = error.what();
  }
}

void App::drawStatusBar() {
  StatusInfo info;
  if (shown_) info.shownLevel = shown_->level;
  info.status = status_;
  info.uiFrameMs = lastFrameMs_;
  info.message = message_;
  angio::drawStatusBar(info, kStatusHeight);
}

}  // namespace angio
