#include "gui/panel_session.h"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace angio {

SessionPanelRequests drawSessionPanel(SessionPanelUi& ui, WidgetRects& rects) {
  SessionPanelRequests requests;
  const SaveLoadClicks clicks =
      drawSaveLoad(ui.path, "session", 190, "Save session", "Load session", rects, true);
  requests.browse = clicks.browse;
  requests.save = clicks.save;
  requests.load = clicks.load;
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
