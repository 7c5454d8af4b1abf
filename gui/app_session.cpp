// Sessions in the app: the Session section (save/load), the "Restore last session" banner, the
// side-panel sections whose open state a session keeps.
#include <exception>
#include <filesystem>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "gui/app.h"
#include "gui/session_file.h"

namespace angio {

namespace fs = std::filesystem;

void App::startSession() {
  panelsToApply_ = doc().panelsOpen;
  const fs::path last = lastSessionPath();
  std::error_code error;
  if (!fs::exists(last, error)) return;
  try {
    Document session = loadSession(last);
    commit(RecentFilesEdit{session.recentFiles});
    // Offered only when started without a volume (on the phantom) and it names something else.
    if (isPhantomName(doc().dataset) && session.dataset != doc().dataset) offeredSession_ = std::move(session);
  } catch (const std::exception& problem) {
    message_ = problem.what();
  }
}

Document App::session() const {
  Document session = doc();
  session.dataset = absoluteDataset(session.dataset);
  return session;
}

void App::applySession(const Document& session) {
  tfHistory_.push(editedTf());
  commit(SessionEdit{session});  // the dataset changes when its load succeeds
  loadSessionCenterlines();      // checked against the session's dataset once that is there
  panelsToApply_ = session.panelsOpen;
  if (session.dataset == data_.name || session.dataset.empty()) return;
  if (isPhantomName(session.dataset))
    message_ = "the session's dataset is a " + session.dataset + "; kept " + data_.name;
  else
    openDataset(session.dataset);
}

bool App::sectionHeader(const char* title) {
  if (const auto pending = panelsToApply_.find(title); pending != panelsToApply_.end()) {
    ImGui::SetNextItemOpen(pending->second, ImGuiCond_Always);
    panelsToApply_.erase(pending);
  }
  const bool open = ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen);
  commit(PanelOpenEdit{title, open});
  return open;
}

void App::drawSessionSection() {
  if (!sectionHeader("Session")) return;
  ImGui::SetNextItemWidth(190);
  ImGui::InputText("##sessionpath", &sessionPath_);
  noteRect("session_path");
  ImGui::SameLine();
  if (ImGui::Button("Save session")) {
    try {
      saveSession(session(), sessionPath_);
      message_ = "saved session " + sessionPath_;
    } catch (const std::exception& error) {
      message_ = error.what();
    }
  }
  noteRect("session_save");
  ImGui::SameLine();
  if (ImGui::Button("Load session")) {
    try {
      applySession(loadSession(sessionPath_));
      message_ = "loaded session " + sessionPath_;
    } catch (const std::exception& error) {
      message_ = error.what();
    }
  }
  noteRect("session_load");
}

// A small window over the top of the image: "Restore last session: <dataset> [Restore] [Dismiss]".
void App::drawSessionBanner() {
  if (!offeredSession_) return;
  ImGui::SetNextWindowPos(ImVec2(12, 12));
  ImGui::SetNextWindowBgAlpha(0.9f);
  ImGui::Begin("##lastsession", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
  if (ImGui::IsWindowAppearing()) ImGui::SetWindowFocus();  // above the viewport, drawn after it
  ImGui::Text("Restore last session: %s", offeredSession_->dataset.c_str());
  ImGui::SameLine();
  const bool restore = ImGui::Button("Restore");
  noteRect("session_restore");
  ImGui::SameLine();
  const bool dismiss = ImGui::Button("Dismiss");
  noteRect("session_dismiss");
  ImGui::End();
  if (restore) applySession(*offeredSession_);
  if (restore || dismiss) offeredSession_.reset();
}

}  // namespace angio
