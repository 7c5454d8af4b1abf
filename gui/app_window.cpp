#include "gui/app_window.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "io/atomic_write.h"
#include "io/input_error.h"
#include "io/image_export.h"
#include "gui/session_file.h"

namespace angio {

namespace {

using Clock = std::chrono::steady_clock;
using Ms = std::chrono::duration<double, std::milli>;
constexpr double kFrameMs = 1000.0 / 60;

void reportGlfwError(int code, const char* description) {
  std::fprintf(stderr, "angioray: GLFW error %d: %s\n", code, description);
}

// Owns GLFW, the window and the ImGui context, in that order of construction.
class Window {
 public:
  explicit Window(const WindowOptions& options) {
    glfwSetErrorCallback(reportGlfwError);
    if (!glfwInit()) throw std::runtime_error("cannot open a window: GLFW failed to initialise");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 2);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    window_ = glfwCreateWindow(options.width, options.height, "angioray", nullptr, nullptr);
    if (!window_) {
      glfwTerminate();
      throw std::runtime_error("cannot open a window: no OpenGL 3.2 context");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    gl_ =
        GlApi::load([](const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); });
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    ImGui_ImplOpenGL3_Init("#version 150");
  }

  ~Window() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window_);
    glfwTerminate();
  }

  GLFWwindow* handle() const { return window_; }
  const GlApi& gl() const { return gl_; }

 private:
  GLFWwindow* window_ = nullptr;
  GlApi gl_;
};

std::atomic<bool> closeRequested{false};

void requestClose(int) { closeRequested.store(true); }

// A file or folder dropped on the window opens like one chosen in the file browser (the first one).
void openDropped(GLFWwindow* window, int count, const char** paths) {
  if (count > 0) static_cast<App*>(glfwGetWindowUserPointer(window))->openDataset(paths[0]);
}

// The last session goes to $XDG_CONFIG_HOME/angioray/last-session.json; a failure is a warning.
void saveLastSession(const App& app) {
  try {
    saveSession(app.session(), lastSessionPath());
  } catch (const std::exception& error) {
    printWarning(error.what());
  }
}

void writeScreenshot(const std::filesystem::path& path, const GlApi& gl, int width, int height) {
  const std::vector<std::uint8_t> rgb = gl.readFrameRgb(width, height);
  Image image = makeImage(width, height);
  for (std::size_t n = 0; n < image.pixels.size(); ++n)
    image.pixels[n] = glm::vec4(rgb[3 * n] / 255.f, rgb[3 * n + 1] / 255.f, rgb[3 * n + 2] / 255.f, 1.f);
  exportImage(image, path);
}

void writeReport(const std::filesystem::path& path, const App& app) {
  writeAtomically(path, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp);
    out << app.report().dump(2) << '\n';
    if (!out) throw std::runtime_error(path.string() + ": cannot be written");
  });
}

// Sleeping while nothing happens: two frames a display frame apart after anything happened (ImGui
// shows some consequences of an input, e.g. a hover after a click, a frame later), then until
// input, a renderer's wake-up or the long tick. Drawing the idle UI twice a second cost about 7 %
// of a core in software GL.
class IdleWait {
 public:
  void wait(double longestSeconds) {
    const double seconds = settleFrames_ < 2 ? kFrameMs / 1000 : std::min(kLongTick, longestSeconds);
    const auto before = Clock::now();
    glfwWaitEventsTimeout(std::max(seconds, 0.0));
    const bool woken = Ms(Clock::now() - before).count() < seconds * 1000 * 0.9;
    settleFrames_ = woken ? 0 : settleFrames_ + 1;
  }
  void busy() { settleFrames_ = 0; }

 private:
  static constexpr double kLongTick = 2;  // s: a SIGTERM is seen at the latest then
  int settleFrames_ = 0;
};

// Seconds left before --quit-after closes the window (a day without it).
double untilQuit(const WindowOptions& options, Clock::time_point opened) {
  if (options.quitAfterSeconds <= 0) return 86400;
  return options.quitAfterSeconds - Ms(Clock::now() - opened).count() / 1000;
}

}  // namespace

bool windowSystemAvailable() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if (!(x11 && *x11) && !(wayland && *wayland)) return false;
  if (!glfwInit()) return false;
  glfwTerminate();
  return true;
}

int runWindow(LoadedDataset dataset, AppStart start, const WindowOptions& options,
              RenderThreads& threads) {
  Window window(options);
  std::signal(SIGINT, requestClose);
  std::signal(SIGTERM, requestClose);
  App app(std::move(dataset), std::move(start), window.gl(), threads, [] { glfwPostEmptyEvent(); });
  glfwSetWindowUserPointer(window.handle(), &app);
  glfwSetDropCallback(window.handle(), openDropped);
  const auto opened = Clock::now();
  double previousFrameMs = 0;
  Clock::time_point previousStart{};
  IdleWait idle;
  bool closing = false;
  while (!closing) {
    closing = glfwWindowShouldClose(window.handle()) || app.wantsToQuit() || closeRequested.load() ||
              (options.quitAfterSeconds > 0 &&
               Ms(Clock::now() - opened).count() > options.quitAfterSeconds * 1000);
    // Draw at display rate only while something moves; otherwise sleep until input or a new
    // frame from the renderer (it wakes us), with a slow tick for the progress bar. Without vsync
    // (e.g. Xvfb) the display rate is about 60 frames per second, and input or a published frame
    // ends that wait too: sleeping through either would add up to a display frame to what the
    // hand waits for.
    const FramePacing pacing = app.pacing();
    switch (pacing) {
      case FramePacing::continuous: {
        const double rest = kFrameMs - Ms(Clock::now() - previousStart).count();
        if (rest > 0) glfwWaitEventsTimeout(rest / 1000);
        else glfwPollEvents();
        break;
      }
      case FramePacing::progress: glfwWaitEventsTimeout(0.1); break;
      case FramePacing::idle: idle.wait(untilQuit(options, opened)); break;
    }
    if (pacing != FramePacing::idle) idle.busy();
    const auto start = Clock::now();
    previousStart = start;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    app.frame(previousFrameMs);
    int width = 0, height = 0;
    glfwGetFramebufferSize(window.handle(), &width, &height);
    window.gl().clearFrame(width, height);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    previousFrameMs = Ms(Clock::now() - start).count();
    if (closing && !options.screenshot.empty())
      writeScreenshot(options.screenshot, window.gl(), width, height);
    glfwSwapBuffers(window.handle());
    app.framePresented();
  }
  if (!options.stateOut.empty()) writeReport(options.stateOut, app);
  saveLastSession(app);
  glfwSetDropCallback(window.handle(), nullptr);
  return 0;
}

}  // namespace angio
