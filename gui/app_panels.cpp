// The side panel of App (its sections, the TF section, the export section) and the status bar.
#include <algorithm>
#include <cstdio>
#include <exception>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "gui/app.h"
#include "gui/app_export.h"
#include "gui/panel_export.h"
#include "gui/panel_rendering.h"
#include "gui/panel_status.h"
#include "gui/panel_tf.h"
#include "gui/panel_view.h"
#include "render/export.h"

namespace angio {

void App::drawSidePanel() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(std::max(io.DisplaySize.x - kPanelWidth, 64.f), 0));
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, std::max(io.DisplaySize.y - kStatusHeight, 64.f)));
  ImGui::Begin("##panel", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
  drawDataSection();
  if (sectionHeader("View")) commit(drawViewPanel(doc().view));
  drawTfSection();
  drawVesselSection();
  drawCprSection();
  if (sectionHeader("Rendering")) commit(drawRenderingPanel(doc()));
  drawExportSection();
  drawSeriesExport();  // part of the Export section
  drawSessionSection();
  ImGui::End();
}

void App::applyTf(const TransferFunction& tf, const std::string& preset) {
  tfHistory_.push(editedTf());
  commit(TfChange{vessel_.editing, tf, preset});
  tfPanel_.editor.selected = tfPanel_.editor.dragging = -1;
}

void App::undoTf() {
  if (tfPanel_.editor.gestureBefore) return;  // not in the middle of an edit
  if (auto previous = tfHistory_.undo(editedTf())) commit(TfChange{vessel_.editing, *previous, ""});
}

void App::redoTf() {
  if (tfPanel_.editor.gestureBefore) return;
  if (auto next = tfHistory_.redo(editedTf())) commit(TfChange{vessel_.editing, *next, ""});
}

void App::drawTfSection() {
  if (!sectionHeader("Transfer function")) return;
  TfPanelInfo info;
  info.editing = vessel_.editing;
  info.targetsShown = vessel_.physical || vessel_.editing != TfTarget::main;
  info.canUndo = tfHistory_.canUndo();
  info.canRedo = tfHistory_.canRedo();
  info.histogram = &histogram_;
  info.presets = &presets_;
  TfPanelRequests requests = drawTfPanel(doc(), tfPanel_, info, widgetRects_);
  if (!requests.message.empty()) message_ = requests.message;
  if (requests.replace) applyTf(requests.replace->tf, requests.replace->preset);
  if (requests.undo) undoTf();
  if (requests.redo) redoTf();
  if (requests.committedBefore) tfHistory_.push(*requests.committedBefore);
  if (requests.edit) commit(*requests.edit);
  if (requests.save) saveEditedTf();
  if (requests.switchTo) switchTfTarget(*requests.switchTo);  // last: the requests above are the old target's
}

void App::saveEditedTf() {
  try {
    saveTransferFunction(editedTf(), tfPanel_.path);
    message_ = "saved " + tfPanel_.path;
  } catch (const std::exception& error) {
    message_ = error.what();
  }
}

void App::drawExportSection() {
  if (!sectionHeader("Export")) return;
  JobInfo job;
  job.running = export_.job.valid();
  job.seconds = std::chrono::duration<double>(Clock::now() - export_.started).count();
  const ExportRequests requests = drawImageExport(export_.ui, job, widgetRects_);
  if (requests.cancel) export_.cancel->store(true);
  if (!requests.start) return;
  export_.cancel = std::make_shared<std::atomic<bool>>(false);
  export_.started = Clock::now();
  export_.job = std::async(std::launch::async, [this, recipe = exportRecipe(), centerlines = exportCenterlines(),
                                                path = export_.ui.path, cancel = export_.cancel] {
    return exportView(data_.volume, centerlines, recipe, path, cancel.get());
  });
  message_ = "exporting " + export_.ui.path;
}

void App::pollExport() {
  if (!export_.job.valid() ||
      export_.job.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
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
