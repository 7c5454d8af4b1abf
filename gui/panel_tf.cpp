#include "gui/panel_tf.h"

#include <cstdio>
#include <exception>
#include <filesystem>

#include <imgui.h>
#include <imgui_stdlib.h>

namespace angio {

namespace {

void drawTargets(const TfPanelInfo& info, TfPanelRequests& requests, WidgetRects& rects) {
  if (!info.targetsShown) return;
  ImGui::TextUnformatted("TF editor edits:");
  for (TfTarget target : {TfTarget::main, TfTarget::focus, TfTarget::context}) {
    ImGui::SameLine();
    char label[32];
    std::snprintf(label, sizeof label, "%s##tftarget", tfTargetName(target));
    if (ImGui::RadioButton(label, info.editing == target) && info.editing != target)
      requests.switchTo = target;
    noteRect(rects, std::string("vg_edit_") + tfTargetName(target));
  }
}

// A preset by its id, a file by its name, an edited TF by its name and "(edited)".
std::string presetLabel(const std::string& preset, const TransferFunction& tf,
                        const std::vector<Preset>& presets) {
  if (preset.empty()) return tf.name + " (edited)";
  for (const Preset& candidate : presets)
    if (candidate.id == preset) return preset;
  return std::filesystem::path(preset).filename().string() + " (file)";
}

void drawPresets(const Document& document, const TfPanelInfo& info, TfPanelRequests& requests) {
  const bool follows = followsMainTf(document, info.editing);
  const std::string preset = follows ? std::string() : presetOf(document, info.editing);
  const std::string current = follows ? followingTfLabel(info.editing)
                                      : presetLabel(preset, tfOf(document, info.editing), *info.presets);
  ImGui::SetNextItemWidth(220);
  if (ImGui::BeginCombo("preset", current.c_str())) {
    if (info.editing != TfTarget::main && ImGui::Selectable(followingTfLabel(info.editing), follows))
      requests.replace = TfChange{info.editing, {}, "", true};
    for (const Preset& candidate : *info.presets) {
      if (!ImGui::Selectable(candidate.id.c_str(), candidate.id == preset)) continue;
      try {
        requests.replace =
            TfChange{info.editing, loadPresetOrFile(candidate.file.string()), candidate.id};
      } catch (const std::exception& error) {
        requests.message = error.what();
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(!info.canUndo);
  requests.undo = ImGui::SmallButton("undo");
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!info.canRedo);
  requests.redo = ImGui::SmallButton("redo");
  ImGui::EndDisabled();
}

void drawFile(TfPanelUi& ui, TfTarget editing, TfPanelRequests& requests, WidgetRects& rects) {
  ImGui::SetNextItemWidth(200);
  ImGui::InputText("##tfpath", &ui.path);
  noteRect(rects, "tf_path");
  requests.browse = drawBrowseButton("tf", rects);
  ImGui::SameLine();
  if (ImGui::Button("load")) {
    try {
      requests.replace = TfChange{editing, loadTransferFunction(ui.path), ui.path};
      requests.message = "loaded " + ui.path;
    } catch (const std::exception& error) {
      requests.message = error.what();
    }
  }
  noteRect(rects, "tf_load");
  ImGui::SameLine();
  requests.save = ImGui::Button("save");
}

}  // namespace

TfPanelRequests drawTfPanel(const Document& document, TfPanelUi& ui, const TfPanelInfo& info,
                            WidgetRects& rects) {
  TfPanelRequests requests;
  drawTargets(info, requests, rects);
  if (info.presets) drawPresets(document, info, requests);
  const std::vector<float> notCounted;
  TfEdit edit = drawTfEditor(tfOf(document, info.editing), info.histogram ? *info.histogram : notCounted,
                             ui.editor);
  requests.committedBefore = std::move(edit.committedBefore);
  if (edit.changed) requests.edit = TfChange{info.editing, std::move(edit.tf), ""};
  drawFile(ui, info.editing, requests, rects);
  return requests;
}

}  // namespace angio
