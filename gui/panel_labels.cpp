#include "gui/panel_labels.h"

#include <imgui.h>

#include "gui/message_row.h"

#include "render/label_styles.h"

namespace angio {

namespace {

constexpr const char* kModeNames[] = {"shown", "hidden", "own TF"};

// The labels worth a row: those with voxels or a style.
bool listed(const std::vector<LabelStyle>& styles, const LabelsPanelInfo& info, int label) {
  if (info.voxels[label] > 0) return true;
  for (const LabelStyle& style : styles)
    if (style.label == label) return true;
  return false;
}

std::string countText(std::uint64_t voxels) {
  char text[32];
  if (voxels >= 1000000) std::snprintf(text, sizeof text, "%.1f M", voxels / 1e6);
  else if (voxels >= 1000) std::snprintf(text, sizeof text, "%.1f k", voxels / 1e3);
  else std::snprintf(text, sizeof text, "%llu", static_cast<unsigned long long>(voxels));
  return text;
}

// One row: color, name, mode, voxel count. The own TF starts as the main TF in the label's color.
void drawLabelRow(LabelStyle& style, const Document& document, const LabelsPanelInfo& info,
                  WidgetRects& rects) {
  ImGui::PushID(style.label);
  const std::string key = "label_" + std::to_string(style.label);
  if (ImGui::ColorEdit3("##color", &style.color.x, ImGuiColorEditFlags_NoInputs) &&
      style.mode == LabelMode::tf)
    style.points = tintedPoints(document.tf.points, style.color);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(130);
  char name[64];
  std::snprintf(name, sizeof name, "%s", style.name.c_str());
  if (ImGui::InputText("##name", name, sizeof name)) style.name = name;
  noteRect(rects, key + "_name");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  int mode = int(style.mode);
  if (ImGui::Combo("##mode", &mode, kModeNames, 3)) {
    style.mode = LabelMode(mode);
    if (style.mode == LabelMode::tf && style.points.empty())
      style.points = tintedPoints(document.tf.points, style.color);
  }
  noteRect(rects, key + "_mode");
  ImGui::SameLine();
  ImGui::Text("%d  %s", style.label, info.counted ? countText(info.voxels[style.label]).c_str() : "...");
  ImGui::PopID();
}

void drawLabelList(std::vector<LabelStyle>& styles, const Document& document,
                   const LabelsPanelInfo& info, WidgetRects& rects) {
  bool any = false;
  for (int label = 1; label <= kMaxLabel; ++label) {
    if (!listed(styles, info, label)) continue;
    drawLabelRow(styleOf(styles, label), document, info, rects);
    any = true;
  }
  if (!any) ImGui::TextDisabled("no labels yet: remove bone, or pick and grow");
}

void drawGrowTool(LabelsPanelUi& ui, const std::vector<LabelStyle>& styles, WidgetRects& rects) {
  ImGui::Checkbox("Pick & grow: click the view", &ui.growTool);
  noteRect(rects, "labels_grow_tool");
  helpMarker(
      "A click finds the point under the cursor (where the ray reaches opacity 0.5, or the MIP "
      "maximum) and labels the connected voxels in the HU range; \"give back\" unlabels the "
      "labelled piece under the cursor. Rotate between clicks as usual.");
  if (!ui.growTool) return;
  if (ImGui::RadioButton("label as", ui.target == GrowTarget::label)) ui.target = GrowTarget::label;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  std::vector<LabelStyle> named = styles;
  if (ImGui::BeginCombo("##growlabel", styleOf(named, ui.growLabel).name.c_str())) {
    for (int label = 1; label <= kMaxLabel; ++label)
      if (ImGui::Selectable(styleOf(named, label).name.c_str(), ui.growLabel == label))
        ui.growLabel = label;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::RadioButton("give back", ui.target == GrowTarget::unlabel)) ui.target = GrowTarget::unlabel;
  noteRect(rects, "labels_give_back");
  if (ui.target == GrowTarget::unlabel) return;
  ImGui::SetNextItemWidth(220);
  double range[2] = {ui.lowHu, ui.highHu};
  if (ImGui::DragScalarN("HU range", ImGuiDataType_Double, range, 2, 5.f, nullptr, nullptr, "%.0f")) {
    ui.lowHu = std::clamp(range[0], -1024.0, 3071.0);
    ui.highHu = std::clamp(range[1], ui.lowHu, 3071.0);
  }
  noteRect(rects, "labels_hu_range");
  ImGui::Checkbox("fill holes (marrow)", &ui.fillHoles);
}

void drawFiles(LabelsPanelUi& ui, const LabelsPanelInfo& info, LabelsPanelResult& result,
               WidgetRects& rects) {
  const SaveLoadClicks clicks = drawSaveLoad(ui.path, "labels", 190, "Save", "Load", rects, true);
  result.browse = clicks.browse;
  result.save = clicks.save;
  result.load = clicks.load;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(".seg.nrrd (3D Slicer, with names and colors), .nrrd, .nii.gz, .mha");
  if (!info.file.empty()) ImGui::TextDisabled("%s", info.file.c_str());
}

}  // namespace

std::vector<ControlPoint> tintedPoints(const std::vector<ControlPoint>& points, glm::vec3 color) {
  std::vector<ControlPoint> tinted = points;
  for (ControlPoint& point : tinted) point.color = color;
  return tinted;
}

LabelsPanelResult drawLabelsPanel(const Document& document, LabelsPanelUi& ui,
                                  const LabelsPanelInfo& info, WidgetRects& rects) {
  LabelsPanelResult result;
  if (!info.hasVolume) return result;
  if (info.busy) {
    ImGui::ProgressBar(float(info.progress), ImVec2(230, 0), info.busyWhat.c_str());
    ImGui::SameLine();
    result.cancel = ImGui::Button("Cancel##labels");
    noteRect(rects, "labels_cancel");
  } else {
    result.removeBoneAndTable = ImGui::Button("Remove bone and table");
    noteRect(rects, "labels_remove_bone");
    helpMarker(
        "Labels bone (1) and the CT table (2) from the density and hides them; contrast-filled "
        "vessels next to bone, calcified plaque and the loaded centerlines' lumen stay.");
  }
  std::vector<LabelStyle> styles = document.tf.labels;
  bool showRemoved = document.labels.showRemoved;
  drawLabelList(styles, document, info, rects);
  ImGui::Checkbox("show removed (translucent)", &showRemoved);
  noteRect(rects, "labels_show_removed");
  drawGrowTool(ui, styles, rects);
  result.undo = drawStepButton("Undo##labels", "labels_undo", info.canUndo && !info.busy,
                               "undo " + info.undoWhat, rects);
  ImGui::SameLine();
  result.redo = drawStepButton("Redo##labels", "labels_redo", info.canRedo && !info.busy,
                               "redo " + info.redoWhat, rects);
  drawFiles(ui, info, result, rects);
  drawMessageRow({{MessageKind::error, info.error}});
  if (styles != document.tf.labels || showRemoved != document.labels.showRemoved)
    result.edit = LabelStylesEdit{styles, showRemoved};
  return result;
}

}  // namespace angio
