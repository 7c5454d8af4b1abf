#pragma once
// What the side panel's sections share: the "(?)" help marker and the record of where named
// widgets were drawn (App::report() lists them so scripted tests can click them).
#include <map>
#include <string>
#include <utility>

#include <imgui.h>
#include <imgui_stdlib.h>

namespace angio {

using WidgetRects = std::map<std::string, std::pair<ImVec2, ImVec2>>;

// The last widget's screen rectangle under `name`.
inline void noteRect(WidgetRects& rects, const std::string& name) {
  rects[name] = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
}

// "..." beside a file field, noted as `<prefix>_browse`: the file browser chooses the field's file.
inline bool drawBrowseButton(const std::string& prefix, WidgetRects& rects) {
  ImGui::SameLine();
  const bool clicked = ImGui::Button(("...##" + prefix).c_str());
  noteRect(rects, prefix + "_browse");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Choose with the file browser");
  return clicked;
}

struct SaveLoadClicks {
  bool save = false, load = false, browse = false;
};

// A file field (with "..." when `browse`) and its Save and Load buttons on one line, noted as
// `<prefix>_path`, `_browse`, `_save` and `_load`.
inline SaveLoadClicks drawSaveLoad(std::string& path, const std::string& prefix, float width,
                                   const std::string& saveLabel, const std::string& loadLabel,
                                   WidgetRects& rects, bool browse = false) {
  SaveLoadClicks clicks;
  ImGui::SetNextItemWidth(width);
  ImGui::InputText(("##" + prefix + "path").c_str(), &path);
  noteRect(rects, prefix + "_path");
  if (browse) clicks.browse = drawBrowseButton(prefix, rects);
  ImGui::SameLine();
  clicks.save = ImGui::Button((saveLabel + "##" + prefix).c_str());
  noteRect(rects, prefix + "_save");
  ImGui::SameLine();
  clicks.load = ImGui::Button((loadLabel + "##" + prefix).c_str());
  noteRect(rects, prefix + "_load");
  return clicks;
}

// An undo or redo button: disabled when there is nothing to step to; its tooltip says what.
inline bool drawStepButton(const std::string& label, const std::string& name, bool enabled,
                           const std::string& tooltip, WidgetRects& rects) {
  ImGui::BeginDisabled(!enabled);
  const bool clicked = ImGui::Button(label.c_str());
  noteRect(rects, name);
  ImGui::EndDisabled();
  if (enabled && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("%s", tooltip.c_str());
  return clicked;
}

inline void helpMarker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

}  // namespace angio
