// The side panel (data, view, transfer function, rendering) and the status bar of App.
#include <algorithm>
#include <cstdio>
#include <exception>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "gui/app.h"
#include "gui/app_export.h"
#include "render/export.h"

namespace angio {

namespace {


struct NamedView {
  const char* label;
  double angleDeg;
  const char* tooltip;
};
// About k (rendering model: theta = 0 looks along +P from the front; the viewer sits at -d).
constexpr NamedView kNamedViews[] = {
    {"AP", 0, "anterior view: looking from the front"},
    {"PA", 180, "posterior view: looking from the back"},
    {"L lat", 90, "left lateral: looking at the patient's left side"},
    {"R lat", 270, "right lateral: looking at the patient's right side"},
    {"LAO 45", 45, "left anterior oblique 45 deg"},
    {"RAO 45", 315, "right anterior oblique 45 deg"},
};

struct NamedWindow {
  const char* label;
  double window, level;
};
constexpr NamedWindow kMipWindows[] = {{"CTA", 800, 300}, {"bone", 1500, 500}, {"soft tissue", 400, 40}};

void helpMarker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

}  // namespace

void App::drawSidePanel() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(std::max(io.DisplaySize.x - kPanelWidth, 64.f), 0));
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, std::max(io.DisplaySize.y - kStatusHeight, 64.f)));
  ImGui::Begin("##panel", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
  drawDataSection();
  drawViewSection();
  drawTfSection();
  drawVesselSection();
  drawCprSection();
  drawRenderingSection();
  drawExportSection();
  drawSeriesExport();  // part of the Export section
  drawSessionSection();
  ImGui::End();
}

void App::drawViewSection() {
  if (!sectionHeader("View")) return;
  ViewState& view = state_.view;
  ImGui::TextUnformatted("axis");
  for (Axis axis : {Axis::i, Axis::j, Axis::k}) {
    ImGui::SameLine();
    if (ImGui::RadioButton(toString(axis), view.axis == axis)) view.axis = axis;
  }
  helpMarker("Rotation axis: k = the patient's long axis (default), i = left-right, j = front-back.");
  float angle = float(view.angleDeg);
  ImGui::SetNextItemWidth(-80);
  if (ImGui::SliderFloat("angle", &angle, 0, 360, "%.1f deg")) view.angleDeg = wrapDegrees(angle);
  helpMarker("Left-drag on the image turns the patient with the mouse; arrow keys +-1 deg (shift: 10).");
  for (std::size_t n = 0; n < std::size(kNamedViews); ++n) {
    if (n % 3) ImGui::SameLine();
    if (ImGui::Button(kNamedViews[n].label, ImVec2(90, 0))) view.angleDeg = kNamedViews[n].angleDeg;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (%.0f deg)", kNamedViews[n].tooltip, kNamedViews[n].angleDeg);
  }
  ImGui::Checkbox("auto-spin", &view.autoSpin);
  ImGui::SameLine();
  float spin = float(view.spinDegreesPerSecond);
  ImGui::SetNextItemWidth(130);
  if (ImGui::SliderFloat("deg/s", &spin, -180, 180, "%.0f")) view.spinDegreesPerSecond = spin;
  float perPixel = float(view.degreesPerPixel);
  ImGui::SetNextItemWidth(130);
  if (ImGui::SliderFloat("deg per pixel (drag)", &perPixel, 0.05f, 2.f, "%.2f")) view.degreesPerPixel = perPixel;
  if (ImGui::Button("reset zoom/pan")) view.zoom = 1, view.panPx = glm::dvec2(0.0);
  ImGui::SameLine();
  ImGui::TextDisabled("zoom %.2fx (wheel), pan: right/middle drag", view.zoom);
}

void App::applyTf(const TransferFunction& tf, const std::string& preset) {
  tfHistory_.push(editedTf());
  editedTf() = tf;
  editedPreset() = preset;
  tfView_.selected = tfView_.dragging = -1;
}

void App::undoTf() {
  if (tfView_.gestureBefore) return;  // not in the middle of an edit
  if (auto previous = tfHistory_.undo(editedTf())) editedTf() = *previous, editedPreset().clear();
}

void App::redoTf() {
  if (tfView_.gestureBefore) return;
  if (auto next = tfHistory_.redo(editedTf())) editedTf() = *next, editedPreset().clear();
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
  if (edit.changed) {
    editedTf() = std::move(edit.tf);
    editedPreset().clear();
  }

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

void App::drawRenderingSection() {
  if (!sectionHeader("Rendering")) return;
  bool mip = state_.mode == Compositing::mip;
  if (ImGui::Checkbox("MIP", &mip)) state_.mode = mip ? Compositing::mip : Compositing::dvr;
  helpMarker("Maximum intensity projection through a window/level instead of the transfer function.");
  if (mip) {
    float window = float(state_.tf.mipWindow), level = float(state_.tf.mipLevel);
    ImGui::SetNextItemWidth(200);
    if (ImGui::SliderFloat("window (HU)", &window, 1, 4000, "%.0f")) state_.tf.mipWindow = window;
    ImGui::SetNextItemWidth(200);
    if (ImGui::SliderFloat("level (HU)", &level, -1024, 3071, "%.0f")) state_.tf.mipLevel = level;
    for (std::size_t n = 0; n < std::size(kMipWindows); ++n) {
      if (n) ImGui::SameLine();
      if (ImGui::SmallButton(kMipWindows[n].label))
        state_.tf.mipWindow = kMipWindows[n].window, state_.tf.mipLevel = kMipWindows[n].level;
    }
  } else {
    ImGui::Checkbox("shading", &state_.shading.enabled);
    if (state_.shading.enabled) {
      float ka = float(state_.shading.ka), kd = float(state_.shading.kd);
      ImGui::SameLine();
      ImGui::SetNextItemWidth(90);
      if (ImGui::SliderFloat("ka", &ka, 0, 1, "%.2f")) state_.shading.ka = ka;
      ImGui::SameLine();
      ImGui::SetNextItemWidth(90);
      if (ImGui::SliderFloat("kd", &kd, 0, 1, "%.2f")) state_.shading.kd = kd;
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
