#pragma once
// The workstation window: the App in a GLFW window with an OpenGL 3.2 core context and the ImGui
// GLFW + OpenGL3 backends.
#include <filesystem>

#include "gui/app.h"

namespace angio {

struct WindowOptions {
  int width = 1400, height = 900;
  double quitAfterSeconds = 0;       // > 0: close by itself (smoke tests under Xvfb)
  std::filesystem::path stateOut;    // App::report() as JSON when the window closes
  std::filesystem::path screenshot;  // the window's last frame, when it closes
};

// A display is there (DISPLAY or WAYLAND_DISPLAY set) and GLFW can talk to it.
bool windowSystemAvailable();

// Runs until the window is closed, SIGINT/SIGTERM arrive (both close it cleanly, writing the
// state and screenshot) or quitAfterSeconds pass.
int runWindow(LoadedDataset dataset, AppStart start, const WindowOptions& options,
              RenderThreads& threads);

}  // namespace angio
