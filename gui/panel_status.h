#pragma once
// The status bar along the window's bottom: the level shown, each level's last time, the
// running render's progress, samples per second, the UI frame time, the last message.
#include <optional>
#include <string>

#include "render/progressive_renderer.h"

namespace angio {

struct StatusInfo {
  std::optional<Quality> shownLevel;  // none: nothing shown yet
  ProgressiveStatus status;
  double uiFrameMs = 0;
  std::string message;  // the last error or notice (the renderer's error, if any, is shown instead)
};

void drawStatusBar(const StatusInfo& info, float height);

}  // namespace angio
