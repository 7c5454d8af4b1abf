// `angioray gui`: load the dataset (or generate the phantom), then open the workstation window or
// run its headless twin.
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>

#include "io/input_error.h"
#include "phantom/phantom.h"
#include "gui/app_window.h"
#include "cli/load_volume.h"
#include "cli/commands.h"
#include "gui/headless.h"
#include "cli/progress_line.h"
#include "cli/size_option.h"
#include "io/tf_file.h"
#include "io/volume_reader.h"

namespace angio {

namespace {

// "WxH" window pixels.
glm::ivec2 parseWindowSize(const std::string& text) {
  int width = 0, height = 0;
  char rest = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &width, &height, &rest) != 2 || width < 320 || height < 240 ||
      width > 8192 || height > 8192)
    throw std::runtime_error("window size '" + text + "' is not WxH with 320x240 .. 8192x8192 pixels");
  return {width, height};
}

LoadedDataset loadDataset(const GuiOptions& options) {
  LoadedDataset dataset;
  if (options.volume.empty()) {
    PhantomOptions phantom;
    phantom.dims = parseSize(options.phantomSize);
    phantom.style = parseStyle(options.phantomStyle);
    ProgressLine progress("generating phantom " + options.phantomSize);
    dataset.volume = generatePhantom(phantom, std::ref(progress)).volume;
    dataset.name = "phantom " + options.phantomSize;
    dataset.description = "generated run-off CTA phantom";
    return dataset;
  }
  return loadedDataset(loadVolumeWithProgress(options.volume), options.volume);
}

// The command line's document, with a session's contents (but its dataset and recent files) over
// it; the app's Workstation wraps the angle.
AppStart initialState(const GuiOptions& options, const LoadedDataset& dataset,
                      const std::optional<Document>& session) {
  AppStart start;
  Document& document = start.document;
  document.dataset = dataset.name;
  const auto axis = parseAxis(options.axis);
  if (!axis) throw std::runtime_error("axis '" + options.axis + "' is not i, j or k");
  document.view.axis = *axis;
  document.view.angleDeg = options.angleDeg;
  document.tf = loadPresetOrFile(options.tf);
  std::error_code error;
  if (std::filesystem::is_regular_file(options.tf, error)) document.tfPreset = options.tf;  // a file
  for (const Preset& preset : listPresets())
    if (preset.id == options.tf) document.tfPreset = preset.id;
  if (options.mip) document.mode = Compositing::mip;
  if (session) {
    Workstation withSession(std::move(document));
    withSession.apply(SessionEdit{*session});
    document = withSession.document();
  }
  start.centerlinesFile = options.centerlines;
  start.labelsFile = options.labels;
  start.motionBudgetMs = options.motionBudgetMs;
  return start;
}

// The session's dataset unless a VOLUME was given (a phantom session: its size).
GuiOptions withSessionDataset(GuiOptions options, const Document& session) {
  if (!options.volume.empty() || session.dataset.empty()) return options;
  if (isPhantomName(session.dataset)) options.phantomSize = session.dataset.substr(8);
  else options.volume = session.dataset;
  return options;
}

}  // namespace

bool canOpenWindow() { return windowSystemAvailable(); }

int runGui(const GuiOptions& options) {
  const glm::ivec2 size = parseWindowSize(options.size);
  // Check what can fail quickly before the (possibly long) load.
  TransferFunction checkTf = loadPresetOrFile(options.tf);
  (void)checkTf;
  if (!options.headless && !options.script.empty())
    throw std::runtime_error("--script drives the headless app; add --headless");
  std::optional<std::vector<ScriptStep>> script;
  if (!options.script.empty()) script = loadScript(options.script);
  if (!options.headless && !windowSystemAvailable())
    throw std::runtime_error(
        "no display to open a window on (DISPLAY/WAYLAND_DISPLAY unset or "
        "unusable); use --headless");
  std::optional<Document> session;
  if (!options.session.empty()) session = loadSession(options.session);
  const GuiOptions effective = session ? withSessionDataset(options, *session) : options;
  LoadedDataset dataset = loadDataset(effective);
  AppStart start = initialState(effective, dataset, session);
  {
    ProgressLine progress("preparing the view");
    dataset.tiles.tiles = std::make_shared<SliceTiles>(
        buildSliceTiles(dataset.volume, start.document.view.axis, std::ref(progress)));
  }
  RenderThreads threads;  // the renderer's arenas and priorities, once for the program
  if (options.headless) {
    HeadlessOptions headless;
    headless.width = size.x;
    headless.height = size.y;
    headless.script = std::move(script);
    headless.screenshot = options.screenshot;
    headless.stateOut = options.stateOut;
    headless.timeoutSeconds = options.timeoutSeconds;
    return runHeadless(std::move(dataset), std::move(start), headless, threads);
  }
  WindowOptions window;
  window.width = size.x;
  window.height = size.y;
  window.quitAfterSeconds = options.quitAfterSeconds;
  window.stateOut = options.stateOut;
  window.screenshot = options.screenshot;
  return runWindow(std::move(dataset), std::move(start), window, threads);
}

}  // namespace angio
