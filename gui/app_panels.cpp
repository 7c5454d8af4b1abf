// The side panel of App (its sections, the TF section, the export section) and the status bar.
#include <algorithm>
#include <cstdio>
#include <exception>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "gui/app.h"
#include "gui/app_export.h"
#include "gui/panel_rendering.h"
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
  tfView_.selected = tfView_.dragging = -1;
}

void App::undoTf() {
  if (tfView_.gestureBefore) return;  // not in the middle of an edit
  if (auto previous = tfHistory_.undo(editedTf())) commit(TfChange{vessel_.editing, *previous, ""});
}

void App::redoTf() {
  if (tfView_.gestureBefore) return;
  if (auto next = tfHistory_.redo(editedTf())) commit(TfChange{vessel_.editing, *next, ""});
}

void App::drawTfSection() {
  if (!sectionHeader("Transfer function")) return;
  drawTfTargetSelector();
  const std::string current = editedPreset().empty() ? editedTf().name + " (edited)" : editedPreset();
  ImGui::SetNextItemWidth(220);
  if (ImGui::BeginCombo("preset", current.c_str())) {
    for (const Preset& preset : presets_) {
      if (!ImGui::Selectable(preset.id.c_str(), preset.id == editedPreset())) continue;
      try {
        applyTf(loadPresetOrFile(preset.file.string()), preset.id);
      } catch (const std::exception& error) {
        message_ = error.what();
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(!tfHistory_.canUndo());
  if (ImGui::SmallButton("undo")) undoTf();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!tfHistory_.canRedo());
  if (ImGui::SmallButton("redo")) redoTf();
  ImGui::EndDisabled();

  TfEdit edit = drawTfEditor(editedTf(), histogram_, tfView_);
  if (edit.committedBefore) tfHistory_.push(*edit.committedBefore);
  if (edit.changed) commit(TfChange{vessel_.editing, std::move(edit.tf), ""});

  ImGui::SetNextItemWidth(230);
  ImGui::InputText("##tfpath", &tfPath_);
  noteRect("tf_path");
  ImGui::SameLine();
  if (ImGui::Button("load")) {
    try {
      applyTf(loadTransferFunction(tfPath_), "");
      message_ = "loaded " + tfPath_;
    } catch (const std::exception& error) {
      message_ = error.what();
    }
  }
  noteRect("tf_load");
  ImGui::SameLine();
  if (ImGui::Button("save")) {
    try {
      saveTransferFunction(editedTf(), tfPath_);
      message_ = "saved " + tfPath_;
    } catch (const std::exception& error) {
      message_ = error.what();
    }
  }
}

void App::drawExportSection() {
  if (!sectionHeader("Export")) return;
  ImGui::SetNextItemWidth(260);
  ImGui::InputText("file##export", &export_.path);
  noteRect("export_path");
  helpMarker("Format by extension: .png (8-bit), .tif (16-bit), .exr (float RGBA). A JSON sidecar "
             "(FILE.json) records every parameter.");
  const double isdMin = 0.1, isdMax = 5;
  ImGui::SetNextItemWidth(120);
  ImGui::SliderScalar("isd", ImGuiDataType_Double, &export_.isd, &isdMin, &isdMax, "%.2f");
  helpMarker("Image sampling distance in voxel units: 0.5 = the high level, 0.25 for print.");
  if (export_.job.valid()) {
    const double seconds = std::chrono::duration<double>(Clock::now() - export_.started).count();
    ImGui::Text("rendering ... %.0f s", seconds);
    ImGui::SameLine();
    if (ImGui::SmallButton("cancel##export")) export_.cancel->store(true);
    return;
  }
  if (ImGui::Button("Export image")) {
    export_.cancel = std::make_shared<std::atomic<bool>>(false);
    export_.started = Clock::now();
    export_.job = std::async(std::launch::async, [this, recipe = exportRecipe(), centerlines = exportCenterlines(),
                                                  path = export_.path, cancel = export_.cancel] {
      return exportView(data_.volume, centerlines, recipe, path, cancel.get());
    });
    message_ = "exporting " + export_.path;
  }
  noteRect("export_button");
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
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - kStatusHeight));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, kStatusHeight));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8, 5));
  ImGui::Begin("##status", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
  ImGui::PopStyleVar();
  if (shown_) {
    ImGui::Text("shown: %s", toString(shown_->level));
  } else {
    ImGui::TextUnformatted("shown: -");
  }
  for (int q = 0; q < kQualityLevels; ++q) {
    ImGui::SameLine(0, 14);
    const LevelTiming& t = status_.levels[q];
    if (t.done) ImGui::Text("%s %.0f ms", toString(Quality(q)), t.ms);
    else ImGui::TextDisabled("%s -", toString(Quality(q)));
  }
  ImGui::SameLine(0, 14);
  if (status_.rendering) {
    char label[48];
    std::snprintf(label, sizeof label, "%s %.0f ms", toString(*status_.rendering), status_.renderingMs);
    ImGui::ProgressBar(float(status_.estimatedProgress()), ImVec2(150, 0), label);
  } else {
    ImGui::ProgressBar(status_.busy ? 0.f : 1.f, ImVec2(150, 0), status_.busy ? "preparing" : "done");
  }
  double samplesPerSecond = 0;
  for (const LevelTiming& t : status_.levels)
    if (t.done) samplesPerSecond = t.samplesPerSecond();
  ImGui::SameLine(0, 14);
  ImGui::Text("%.0f Msamples/s", samplesPerSecond * 1e-6);
  ImGui::SameLine(0, 14);
  ImGui::Text("UI %.1f ms", lastFrameMs_);
  if (!message_.empty() || !status_.error.empty()) {
    ImGui::SameLine(0, 14);
    ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "%s", status_.error.empty() ? message_.c_str() : status_.error.c_str());
  }
  ImGui::End();
}

}  // namespace angio
