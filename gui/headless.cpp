#include "gui/headless.h"

#include <GL/osmesa.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <thread>

#include <imgui.h>
#include <backends/imgui_impl_opengl2.h>

#include "io/atomic_write.h"
#include "io/image_export.h"

namespace angio {

namespace {

using Clock = std::chrono::steady_clock;
using Ms = std::chrono::duration<double, std::milli>;
constexpr double kFrameMs = 1000.0 / 60;  // paced like a 60 Hz display

// What the scripted "user" holds down right now.
struct ScriptedInput {
  ImVec2 mouse{-1, -1};
  bool buttons[3] = {false, false, false};
  float wheel = 0;  // consumed by one frame
  int key = -1;     // ImGuiKey held, -1 none
  bool ctrl = false, shift = false;
};

struct NamedKey {
  const char* name;
  int key;
};
// Key names of the script, mapped to ImGuiKey (the headless key map is the identity).
constexpr NamedKey kKeys[] = {{"Tab", ImGuiKey_Tab},
                              {"Left", ImGuiKey_LeftArrow},
                              {"Right", ImGuiKey_RightArrow},
                              {"Up", ImGuiKey_UpArrow},
                              {"Down", ImGuiKey_DownArrow},
                              {"PageUp", ImGuiKey_PageUp},
                              {"PageDown", ImGuiKey_PageDown},
                              {"Home", ImGuiKey_Home},
                              {"End", ImGuiKey_End},
                              {"Delete", ImGuiKey_Delete},
                              {"Backspace", ImGuiKey_Backspace},
                              {"Space", ImGuiKey_Space},
                              {"Enter", ImGuiKey_Enter},
                              {"Escape", ImGuiKey_Escape},
                              {"A", ImGuiKey_A},
                              {"C", ImGuiKey_C},
                              {"V", ImGuiKey_V},
                              {"X", ImGuiKey_X},
                              {"Y", ImGuiKey_Y},
                              {"Z", ImGuiKey_Z}};

int keyOf(const std::string& name) {
  for (const NamedKey& named : kKeys)
    if (name == named.name) return named.key;
  return -1;
}

void writeJson(const std::filesystem::path& path, const nlohmann::json& json) {
  writeAtomically(path, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp);
    out << json.dump(2) << '\n';
    if (!out) throw std::runtime_error(path.string() + ": cannot be written");
  });
}

class HeadlessSession {
 public:
  HeadlessSession(LoadedDataset dataset, AppStart start, const HeadlessOptions& options,
                  RenderThreads& threads)
      : options_(options), pixels_(std::size_t(options.width) * options.height * 4) {
    context_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!context_) throw std::runtime_error("OSMesa: cannot create an OpenGL context");
    if (!OSMesaMakeCurrent(context_, pixels_.data(), GL_UNSIGNED_BYTE, options.width, options.height))
      throw std::runtime_error("OSMesa: cannot make the context current");
    OSMesaPixelStore(OSMESA_Y_UP, 0);  // row 0 of pixels_ is the top of the window
    gl_ = GlApi::load(
        [](const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); });
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(options.width), float(options.height));
    for (int key = 0; key < ImGuiKey_COUNT; ++key) io.KeyMap[key] = key;
    ImGui_ImplOpenGL2_Init();
    app_ = std::make_unique<App>(std::move(dataset), std::move(start), gl_, threads, [this] { wake(); });
  }

  ~HeadlessSession() {
    app_.reset();  // its texture belongs to this context
    ImGui_ImplOpenGL2_Shutdown();
    ImGui::DestroyContext();
    OSMesaDestroyContext(context_);
  }

  void run() {
    if (!options_.script) {
      waitLevel(Quality::high);
    } else {
      for (const ScriptStep& step : *options_.script) perform(step);
    }
    frame();  // what is on screen reflects everything done
    if (!options_.screenshot.empty()) screenshot(options_.screenshot);
    if (!options_.stateOut.empty()) writeJson(options_.stateOut, app_->report());
  }

 private:
  void perform(const ScriptStep& step) {
    using Kind = ScriptStep::Kind;
    switch (step.kind) {
      case Kind::move: input_.mouse = toImVec(step.at), frame(); break;
      case Kind::click: click(step.at, step.button); break;
      case Kind::clickMm: click(screenOf(step.pointMm), 0); break;
      case Kind::doubleClick: click(step.at, 0), click(step.at, 0); break;
      case Kind::drag: drag(step); break;
      case Kind::press:
      case Kind::release:
        input_.mouse = toImVec(step.at);
        frame();
        input_.buttons[step.button] = step.kind == Kind::press;
        frame();
        break;
      case Kind::wheel:
        input_.mouse = toImVec(step.at);
        input_.ctrl = step.ctrl, input_.shift = step.shift;
        frame();
        input_.wheel = float(step.value);
        frame();
        input_.ctrl = input_.shift = false;
        break;
      case Kind::key: pressKey(step.text); break;
      case Kind::text:
        for (unsigned char c : step.text) ImGui::GetIO().AddInputCharacter(c);
        frame();
        break;
      case Kind::waitMs: waitMs(step.value); break;
      case Kind::waitLevel: waitLevel(step.level); break;
      case Kind::screenshot: frame(), screenshot(step.text); break;
      case Kind::state: frame(), writeJson(step.text, app_->report()); break;
      case Kind::open: app_->openDataset(step.text), frame(); break;
    }
  }

  static ImVec2 toImVec(glm::vec2 p) { return ImVec2(p.x, p.y); }

  glm::vec2 screenOf(const glm::dvec3& physicalMm) {
    frame();
    const std::optional<glm::vec2> at = app_->screenOfPhysical(physicalMm);
    if (!at) throw std::runtime_error("script: click_mm before an image is shown");
    return *at;
  }

  void click(glm::vec2 at, int button) {
    input_.mouse = toImVec(at);
    frame();
    input_.buttons[button] = true;
    frame();
    input_.buttons[button] = false;
    frame();
  }

  void drag(const ScriptStep& step) {
    input_.mouse = toImVec(step.at);
    input_.ctrl = step.ctrl, input_.shift = step.shift;
    frame();
    input_.buttons[step.button] = true;
    frame();
    for (int n = 1; n <= step.steps; ++n) {
      const glm::vec2 p = step.at + (step.to - step.at) * (float(n) / float(step.steps));
      input_.mouse = toImVec(p);
      frame();
    }
    input_.buttons[step.button] = false;
    frame();
    input_.ctrl = input_.shift = false;
  }

  void pressKey(const std::string& combination) {
    std::string name = combination;
    input_.ctrl = input_.shift = false;
    for (std::size_t plus; (plus = name.find('+')) != std::string::npos; name = name.substr(plus + 1)) {
      const std::string modifier = name.substr(0, plus);
      if (modifier == "Ctrl") input_.ctrl = true;
      else if (modifier == "Shift") input_.shift = true;
      else throw std::runtime_error("script: unknown modifier " + modifier + " in " + combination);
    }
    input_.key = keyOf(name);
    if (input_.key < 0) throw std::runtime_error("script: unknown key " + combination);
    frame();
    input_.key = -1;
    frame();
    input_.ctrl = input_.shift = false;
  }

  void waitMs(double ms) {
    const auto end = Clock::now() + std::chrono::microseconds(std::int64_t(ms * 1000));
    do waitingFrame(end);
    while (Clock::now() < end);
  }

  void waitLevel(Quality level) {
    const auto deadline =
        Clock::now() + std::chrono::milliseconds(std::int64_t(options_.timeoutSeconds * 1000));
    frame();
    while (!app_->settled(level)) {
      if (Clock::now() > deadline)
        throw std::runtime_error(std::string("headless: no ") + toString(level) + " image within " +
                                 std::to_string(int(options_.timeoutSeconds)) + " s");
      waitingFrame(deadline);
    }
  }

  // Called by the renderer's thread when it publishes a frame or goes idle.
  void wake() {
    {
      std::lock_guard lock(wakeMutex_);
      woken_ = true;
    }
    wakeCondition_.notify_one();
  }

  // Nobody is typing or moving the mouse: like the window, wait for the renderer (or a slow tick)
  // unless something on screen moves, then draw a frame.
  void waitingFrame(Clock::time_point deadline) {
    const FramePacing pacing = app_->pacing();
    if (pacing != FramePacing::continuous) {
      const auto tick =
          Clock::now() + std::chrono::milliseconds(pacing == FramePacing::progress ? 100 : 500);
      std::unique_lock lock(wakeMutex_);
      wakeCondition_.wait_until(lock, std::min(tick, deadline), [&] { return woken_; });
      woken_ = false;
    }
    frame();
  }

  void applyInput() {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = input_.mouse;
    for (int b = 0; b < 3; ++b) io.MouseDown[b] = input_.buttons[b];
    io.MouseWheel = input_.wheel;
    input_.wheel = 0;
    std::fill(std::begin(io.KeysDown), std::end(io.KeysDown), false);
    if (input_.key >= 0) io.KeysDown[input_.key] = true;
    io.KeyCtrl = input_.ctrl;
    io.KeyShift = input_.shift;
  }

  // One UI frame, paced to 60 Hz so that time-based behaviour (double-click, spin) is realistic.
  // Like a 60 Hz display, a frame the renderer publishes meanwhile shows at the next tick (drawing
  // it at once costs the render more CPU than it saves: bench/input_latency.sh).
  void frame() {
    const auto start = Clock::now();
    ImGuiIO& io = ImGui::GetIO();
    io.DeltaTime = float(std::max(Ms(start - lastFrameStart_).count(), 1.0) * 1e-3);
    if (lastFrameStart_ == Clock::time_point{}) io.DeltaTime = float(kFrameMs * 1e-3);
    lastFrameStart_ = start;
    applyInput();
    ImGui_ImplOpenGL2_NewFrame();
    app_->frame(previousFrameMs_);
    gl_.clearFrame(options_.width, options_.height);
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    gl_.finish();
    app_->framePresented();
    previousFrameMs_ = Ms(Clock::now() - start).count();
    const double rest = kFrameMs - previousFrameMs_;
    if (rest > 0) std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(rest));
  }

  void screenshot(const std::filesystem::path& path) {
    Image image = makeImage(options_.width, options_.height);
    for (std::size_t n = 0; n < image.pixels.size(); ++n) {
      const std::uint8_t* p = &pixels_[n * 4];
      image.pixels[n] = glm::vec4(p[0] / 255.f, p[1] / 255.f, p[2] / 255.f, 1.f);
    }
    exportImage(image, path);
    std::printf("wrote %s\n", path.string().c_str());
  }

  HeadlessOptions options_;
  std::mutex wakeMutex_;
  std::condition_variable wakeCondition_;
  bool woken_ = false;
  std::vector<std::uint8_t> pixels_;  // the OSMesa framebuffer, RGBA
  OSMesaContext context_ = nullptr;
  GlApi gl_;
  std::unique_ptr<App> app_;
  ScriptedInput input_;
  Clock::time_point lastFrameStart_{};
  double previousFrameMs_ = 0;
};

}  // namespace

int runHeadless(LoadedDataset dataset, AppStart start, const HeadlessOptions& options,
                RenderThreads& threads) {
  HeadlessSession session(std::move(dataset), std::move(start), options, threads);
  session.run();
  return 0;
}

}  // namespace angio

// LeakSanitizer (sanitizer builds only; unused functions otherwise): the software OpenGL stacks
// keep a few small allocations for the life of the process (OSMesa's framebuffer bookkeeping,
// LLVM's JIT, Mesa's GLX driver and Xlib under the window); they are not ours to free. The list
// of suppressions used is not printed: it would add lines to the one-line error messages.
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\nleak:libLLVM\nleak:libglapi.so\nleak:libGLX_mesa.so\nleak:libgallium\n"
         "leak:swrast_dri.so\nleak:libX11.so\nleak:libglfw.so\n";
}
