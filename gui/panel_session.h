#pragma once
// The Session section (a session file's path, Save and Load) and the "Restore last session"
// banner over the image. Both return what the user asked for; the app does it.
#include <string>

#include "gui/panel_widgets.h"

namespace angio {

struct SessionPanelUi {
  std::string path = "session.json";
};

struct SessionPanelRequests {
  bool save = false, load = false;  // to or from ui.path
  bool browse = false;              // "...": the file browser fills ui.path
};

SessionPanelRequests drawSessionPanel(SessionPanelUi& ui, WidgetRects& rects);

enum class BannerChoice { none, restore, dismiss };

// A small window at the image's top left: "Restore last session: <dataset> [Restore] [Dismiss]".
BannerChoice drawSessionBanner(const std::string& dataset, WidgetRects& rects);

}  // namespace angio
