#include "gui/panel_vessels.h"

#include <cstdio>

#include <imgui.h>

#include "gui/message_row.h"

namespace angio {

namespace {

void drawTool(VesselsPanelUi& ui, const VesselsPanelInfo& info, VesselsPanelResult& result,
              WidgetRects& rects) {
  ImGui::Checkbox("Trace: click the view", &ui.traceTool);
  noteRect(rects, "vessels_trace_tool");
  helpMarker(
      "A click (not a drag) finds the point under the cursor (opacity 0.5, or the MIP maximum), "
      "snaps it to the lumen's centre and traces the selected path through its points. Rotate "
      "between clicks as usual.");
  if (!ui.traceTool) return;
  if (ImGui::RadioButton("add points", ui.click == TraceClick::addPoint))
    ui.click = TraceClick::addPoint;
  noteRect(rects, "vessels_add_points");
  ImGui::SameLine();
  if (ImGui::Button("New path")) {
    ui.selectedPath = -1;
    ui.selectedPoint = -1;
    ui.click = TraceClick::addPoint;
  }
  noteRect(rects, "vessels_new_path");
  ImGui::SameLine();
  if (ImGui::RadioButton("trace downstream", ui.click == TraceClick::downstream))
    ui.click = TraceClick::downstream;
  noteRect(rects, "vessels_downstream");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the next click seeds the vessel tree below it");
  if (info.busy) {
    char overlay[96];
    if (info.progress >= 0) std::snprintf(overlay, sizeof overlay, "%s", info.busyWhat.c_str());
    else std::snprintf(overlay, sizeof overlay, "%s  %.0f s", info.busyWhat.c_str(), info.seconds);
    ImGui::ProgressBar(info.progress >= 0 ? float(info.progress) : 0.f, ImVec2(260, 0), overlay);
    ImGui::SameLine();
    result.cancel = ImGui::Button("Cancel##vessels");
    noteRect(rects, "vessels_cancel");
  } else {
    drawBlankWidgetRows(1);  // the bar's row stays: every click starts the tracer
  }
  const std::string queued =
      info.busy && info.queued > 0 ? std::to_string(info.queued) + " click(s) wait for the tracer" : "";
  drawMessageRow({{MessageKind::note, queued}});
}

// A tracer setting the user may fix (checkbox, then its value) or leave to the tracer; noted as
// `<name>` (the checkbox) and `<name>_hu`. True once changed: typed values when the field lets go
// (every keystroke would start the tracer over).
bool drawFixedHu(const char* label, bool& fixed, double& hu, const std::string& name,
                 WidgetRects& rects) {
  ImGui::PushID(label);
  bool changed = ImGui::Checkbox(label, &fixed);
  noteRect(rects, name);
  ImGui::SameLine();
  ImGui::BeginDisabled(!fixed);
  ImGui::SetNextItemWidth(70);
  ImGui::InputDouble("HU", &hu, 0, 0, "%.0f");
  changed |= ImGui::IsItemDeactivatedAfterEdit();
  noteRect(rects, name + "_hu");
  ImGui::EndDisabled();
  ImGui::PopID();
  return changed;
}

void drawContrast(VesselsPanelUi& ui, const VesselsPanelInfo& info, VesselsPanelResult& result,
                  WidgetRects& rects) {
  if (info.contrast)
    ImGui::Text("contrast %.0f .. %.0f HU", info.contrast->lowHu, info.contrast->highHu);
  else ImGui::TextDisabled("contrast: from the first click");
  result.settingsChanged |= drawFixedHu("tissue", ui.fixedTissue, ui.tissueHu, "vessels_tissue", rects);
  ImGui::SameLine();
  result.settingsChanged |=
      drawFixedHu("calcium from", ui.fixedCalcium, ui.calciumHu, "vessels_calcium", rects);
  helpMarker(
      "What surrounds the vessels and where calcium begins, unless the tracer's own; uncalibrated "
      "data (e.g. the vmtk aorta) need about 300 and 3000. A change starts the contrast range "
      "over.");
}

void drawPathRow(const VesselPath& path, int index, VesselsPanelUi& ui, bool& remove,
                 WidgetRects& rects) {
  ImGui::PushID(index);
  char label[160];
  std::snprintf(label, sizeof label, "%s   %zu pts, %.0f mm, %zu control", path.name.c_str(),
                path.centerline.points.size(), pathLengthMm(path.centerline),
                path.controlPointsMm.size());
  if (ImGui::Selectable(label, ui.selectedPath == index, 0, ImVec2(330, 0))) {
    ui.selectedPath = index;
    ui.selectedPoint = -1;
  }
  noteRect(rects, "vessels_path_" + std::to_string(index));
  ImGui::SameLine();
  remove = ImGui::SmallButton("x");
  noteRect(rects, "vessels_delete_" + std::to_string(index));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("delete %s", path.name.c_str());
  ImGui::PopID();
}

void drawPathList(const VesselsState& vessels, VesselsPanelUi& ui, VesselsPanelResult& result,
                  WidgetRects& rects) {
  if (vessels.paths.empty()) ImGui::TextDisabled("no paths: trace one, or load a file");
  for (int n = 0; n < int(vessels.paths.size()); ++n) {
    bool remove = false;
    drawPathRow(vessels.paths[n], n, ui, remove, rects);
    if (!remove) continue;
    std::vector<VesselPath> rest = vessels.paths;
    rest.erase(rest.begin() + n);
    result.edit = VesselPathsEdit{rest};
    result.what = "delete " + vessels.paths[n].name;
    ui.selectedPath = -1;
  }
}

void drawSelectedPath(const VesselsState& vessels, VesselsPanelUi& ui, VesselsPanelResult& result,
                      WidgetRects& rects) {
  if (ui.selectedPath < 0 || ui.selectedPath >= int(vessels.paths.size())) return;
  const VesselPath& path = vessels.paths[ui.selectedPath];
  if (!ui.renaming) ui.rename = path.name;  // the field shows the name unless being typed in
  char name[96];
  std::snprintf(name, sizeof name, "%s", ui.rename.c_str());
  ImGui::SetNextItemWidth(200);
  if (ImGui::InputText("name##vesselpath", name, sizeof name)) ui.rename = name;
  ui.renaming = ImGui::IsItemActive();
  noteRect(rects, "vessels_rename");
  if (ImGui::IsItemDeactivatedAfterEdit() && !ui.rename.empty() && ui.rename != path.name) {
    std::vector<VesselPath> renamed = vessels.paths;
    renamed[ui.selectedPath].name = ui.rename;
    renamed[ui.selectedPath].centerline.name = ui.rename;
    result.edit = VesselPathsEdit{renamed};
    result.what = "rename " + path.name + " to " + ui.rename;
  }
  if (path.controlPointsMm.empty()) ImGui::TextDisabled("read from a file or traced downstream");
  for (int n = 0; n < int(path.controlPointsMm.size()); ++n) {
    const glm::dvec3& p = path.controlPointsMm[n];
    char label[96];
    std::snprintf(label, sizeof label, "%d  (%.1f, %.1f, %.1f) mm", n + 1, p.x, p.y, p.z);
    if (ImGui::Selectable(label, ui.selectedPoint == n)) ui.selectedPoint = n;
    noteRect(rects, "vessels_point_" + std::to_string(n));
  }
  if (ui.selectedPoint < 0 || ui.selectedPoint >= int(path.controlPointsMm.size())) return;
  if (ImGui::RadioButton("move: click its new place", ui.click == TraceClick::movePoint)) {
    ui.click = TraceClick::movePoint;
    ui.traceTool = true;
  }
  noteRect(rects, "vessels_move_point");
  ImGui::SameLine();
  result.removePoint = ImGui::Button("Delete point");
  noteRect(rects, "vessels_delete_point");
}

void drawUndoAndFiles(VesselsPanelUi& ui, const VesselsPanelInfo& info, VesselsPanelResult& result,
                      WidgetRects& rects) {
  result.undo = drawStepButton("Undo##vessels", "vessels_undo", info.canUndo,
                               "undo " + info.undoWhat + " (Ctrl+Z)", rects);
  ImGui::SameLine();
  result.redo = drawStepButton("Redo##vessels", "vessels_redo", info.canRedo,
                               "redo " + info.redoWhat + " (Ctrl+Shift+Z)", rects);
  const SaveLoadClicks clicks = drawSaveLoad(ui.path, "vessels", 230, "Save", "Load", rects);
  result.save = clicks.save;
  result.load = clicks.load;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip(".mrk.json (3D Slicer), .vtp (vmtk), .csv");
  result.browseSave = ImGui::Button("Save as...");
  noteRect(rects, "vessels_save_as");
  ImGui::SameLine();
  result.browseLoad = ImGui::Button("Open...##vessels");
  noteRect(rects, "vessels_open");
  if (!info.file.empty())
    ImGui::TextDisabled("%s%s", info.file.c_str(), info.unsaved ? " (changed)" : "");
}

}  // namespace

VesselsPanelResult drawVesselsPanel(const VesselsState& vessels, VesselsPanelUi& ui,
                                    const VesselsPanelInfo& info, WidgetRects& rects) {
  VesselsPanelResult result;
  if (!info.hasVolume) return result;
  drawTool(ui, info, result, rects);
  drawContrast(ui, info, result, rects);
  drawPathList(vessels, ui, result, rects);
  drawSelectedPath(vessels, ui, result, rects);
  drawUndoAndFiles(ui, info, result, rects);
  drawMessageRow({{MessageKind::error, info.error}, {MessageKind::error, info.problem}});
  return result;
}

}  // namespace angio
