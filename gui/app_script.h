#pragma once
// Scripted input for the headless twin: a JSON list of steps, each an object with one key:
//   {"move": [x, y]}                       mouse to window pixel (x, y)
//   {"click": [x, y], "button": 0}         press and release (0 left, 1 right, 2 middle)
//   {"double_click": [x, y]}
//   {"click_mm": [x, y, z]}                a left click where a physical point (LPS mm, as
//                                          centerline files hold it) is on the shown image
//   {"drag": {"from": [x, y], "to": [x, y], "button": 0, "steps": 10}}
//   {"press": [x, y], "button": 0}         button down (held through later moves and waits)
//   {"release": [x, y], "button": 0}
//   {"wheel": {"at": [x, y], "delta": 1}}  positive = zoom in
//   {"key": "Left"}                        also "Shift+Left", "Ctrl+Z", "Ctrl+A", "Right", "Up", ...
//   {"text": "view.png"}                   typed into the focused text field
//   {"wait_ms": 200}                       keep running frames
//   {"wait_level": "high"}                 until the newest request shows that level (or stops)
//                                          and no export is running
//   {"screenshot": "file.png"}             the window as it is now
//   {"state": "file.json"}                 the app's state and runtime numbers
//   {"open": "volume.mha"}                 open a volume file or DICOM folder, as a drop on the
//                                          window does (wait_level waits for the load too)
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/render_params.h"

namespace angio {

struct ScriptStep {
  enum class Kind {
    move,
    click,
    clickMm,
    doubleClick,
    drag,
    press,
    release,
    wheel,
    key,
    text,
    waitMs,
    waitLevel,
    screenshot,
    state,
    open
  };
  Kind kind = Kind::move;
  glm::vec2 at{0.f};        // move, click, wheel position; drag start
  glm::vec2 to{0.f};        // drag end
  glm::dvec3 pointMm{0.0};  // click_mm
  int button = 0;
  bool ctrl = false, shift = false;  // wheel, drag: held during the step ("hold": "Ctrl+Shift")
  int steps = 10;                    // drag: mouse moves between press and release
  double value = 0;                  // wait_ms, wheel delta
  Quality level = Quality::high;
  std::string text;  // key name, typed text, output file
};

// The bounds of one script: its steps, the mouse moves of its drags, its wait_ms in all.
inline constexpr std::size_t kMaxScriptSteps = 5000;
inline constexpr double kMaxScriptWaitMs = 600000;

// Throws InputError naming the file and the step (numbered from 1) for anything malformed.
std::vector<ScriptStep> loadScript(const std::filesystem::path& path);
std::vector<ScriptStep> parseScript(const std::string& json, const std::filesystem::path& source);

}  // namespace angio
