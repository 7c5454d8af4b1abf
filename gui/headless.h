#pragma once
// The headless twin of the workstation window: the same App in an OSMesa (software OpenGL)
// context with the ImGui OpenGL2 backend, driven by scripted input (gui/app_script.h), writing
// screenshots. No X server needed.
#include <filesystem>
#include <optional>
#include <vector>

#include "gui/app.h"
#include "gui/app_script.h"

namespace angio {

struct HeadlessOptions {
  int width = 1280, height = 800;
  std::optional<std::vector<ScriptStep>> script;  // none: run until the high image is shown
  std::filesystem::path screenshot;               // written at the end (PNG/TIFF/EXR by extension)
  std::filesystem::path stateOut;                 // App::report() as JSON at the end
  double timeoutSeconds = 300;                    // for each wait_level (and the no-script wait)
};

int runHeadless(LoadedDataset dataset, AppStart start, const HeadlessOptions& options,
                RenderThreads& threads);

}  // namespace angio
