// Sessions in the app: the Session section's save and load and the "Restore last session" banner
// (gui/panel_session.h), the side-panel sections whose open state a session keeps.
#include <exception>
#include <filesystem>

#include <imgui.h>

#include "gui/app.h"
#include "gui/panel_session.h"
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
    if (isPhantomName(doc().dataset) && session.dataset != doc().dataset)
      offeredSession_ = std::move(session);
  } catch (const std::exception& problem) {
    message_ = problem.what();
  }
}

Document App::session() const {
  Document session = doc();
  session.dataset = absoluteDataset(session.dataset);
  return session;
}

// A session naming another dataset is applied once that has loaded: one that fails to load (or
// is cancelled) leaves the app as it was, with the error shown.
void App::applySession(const Document& session) {
  const bool sameDataset = session.dataset == data_.name || session.dataset.empty();
  if (sameDataset || isPhantomName(session.dataset)) {
    commitSession(session);
    if (!sameDataset)
      message_ = "the session's dataset is a " + session.dataset + "; kept " + data_.name;
    return;
  }
  if (load_.running()) {
    message_ = "still loading " + loadPath_ + "; cancel it first";
    return;
  }
  pendingSession_ = session;
  openDataset(session.dataset, true);
}

// The session onto the dataset shown.
void App::commitSession(const Document& session) {
  tfTargets_.history().push(editedTf());
  Document onShown = session;
  onShown.dataset = data_.name;
  commit(SessionEdit{onShown});
  vessels_.undo.clear();
  vessels_.redo.clear();
  vessels_.ui.selectedPath = -1;
  loadSessionCenterlines();
  panelsToApply_ = session.panelsOpen;
  if (!session.labels.file.empty()) startLabelRead(session.labels.file);
}

bool App::sectionHeader(const char* title, bool openByDefault) {
  if (const auto pending = panelsToApply_.find(title); pending != panelsToApply_.end()) {
    ImGui::SetNextItemOpen(pending->second, ImGuiCond_Always);
    panelsToApply_.erase(pending);
  }
  const bool open = ImGui::CollapsingHeader(
      title, openByDefault ? ImGuiTreeNodeFlags_DefaultOpen : ImGuiTreeNodeFlags_None);
  noteRect(std::string("section_") + title);
  commit(PanelOpenEdit{title, open});
  return open;
}

void App::drawSessionSection() {
  if (!sectionHeader("Session")) return;
  const SessionPanelRequests requests = drawSessionPanel(sessionPanel_, widgetRects_);
  const std::string& path = sessionPanel_.path;
  if (requests.browse) browseFor(BrowserPurpose::sessionFile, path);
  try {
    if (requests.save) {
      saveSession(session(), path);
      message_ = "saved session " + path;
    }
    if (requests.load) {
      applySession(loadSession(path));
      message_ = "loaded session " + path;
    }
  } catch (const std::exception& error) {
    message_ = error.what();
  }
}

void App::drawSessionBanner() {
  if (!offeredSession_) return;
  const BannerChoice choice = angio::drawSessionBanner(offeredSession_->dataset, widgetRects_);
  if (choice == BannerChoice::restore) applySession(*offeredSession_);
  if (choice != BannerChoice::none) offeredSession_.reset();
}

}  // namespace angio
