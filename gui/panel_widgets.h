#pragma once
// What the side panel's sections share: the "(?)" help marker and the record of where named
// widgets were drawn (App::report() lists them so scripted tests can click them).
#include <map>
#include <string>
#include <utility>

#include <imgui.h>

namespace angio {

using WidgetRects = std::map<std::string, std::pair<ImVec2, ImVec2>>;

// The last widget's screen rectangle under `name`.
inline void noteRect(WidgetRects& rects, const std::string& name) {
  rects[name] = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
}

inline void helpMarker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

}  // namespace angio
