#include "gui/panel_session.h"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace angio {

SessionPanelRequests drawSessionPanel(SessionPanelUi& ui, WidgetRects& rects) {
  SessionPanelRequests requests;
  ImGui::SetNextItemWidth(190);
  ImGui::InputText("##sessionpath", &ui.path);
  noteRect(rects, "session_path");
  ImGui::SameLine();
  requests.save = ImGui::Button("Save session");
  noteRect(rects, "session_save");
  ImGui::SameLine();
  requests.load = ImGui::Button("Load session");
  noteRect(rects, "session_load");
  return requests;
}

BannerChoice drawSessionBanner(const std::string& dataset, WidgetRects& rects) {
  ImGui::SetNextWindowPos(ImVec2(12, 12));
  ImGui::SetNextWindowBgAlpha(0.9f);
  ImGui::Begin("##lastsession", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing);
  if (ImGui::IsWindowAppearing()) ImGui::SetWindowFocus();  // above the viewport, drawn after it
  ImGui::Text("Restore last session: %s", dataset.c_str());
  ImGui::SameLine();
  const bool restore = ImGui::Button("Restore");
  noteRect(rects, "session_restore");
  ImGui::SameLine();
  const bool dismiss = ImGui::Button("Dismiss");
  noteRect(rects, "session_dismiss");
  ImGui::End();
  return restore ? BannerChoice::restore : dismiss ? BannerChoice::dismiss : BannerChoice::none;
}

}  // namespace angio
