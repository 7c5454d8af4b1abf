#include "gui/app_script.h"

#include <cstdint>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "io/input_error.h"
#include "io/json_text.h"
#include "io/shown_text.h"

namespace angio {

namespace {

using Json = nlohmann::json;

struct StepParser {
  const std::filesystem::path& source;
  std::string where;  // "step 3"

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(source, where + ": " + problem);
  }

  glm::vec2 point(const Json& value, const char* what) const {
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
      fail(std::string(what) + " must be [x, y] in window pixels");
    return {value[0].get<float>(), value[1].get<float>()};
  }
  double number(const Json& value, const char* what, double lo, double hi) const {
    if (!value.is_number()) fail(std::string(what) + " must be a number");
    const double n = value.get<double>();
    if (!(n >= lo && n <= hi)) fail(std::string(what) + " out of range");
    return n;
  }
  std::string string(const Json& value, const char* what) const {
    if (!value.is_string() || value.get<std::string>().empty())
      fail(std::string(what) + " must be a non-empty string");
    return value.get<std::string>();
  }
  int button(const Json& object) const {
    return object.contains("button") ? int(number(object["button"], "button", 0, 2)) : 0;
  }
  // "hold": "Ctrl", "Shift" or "Ctrl+Shift", the modifiers held during a wheel or a drag.
  void hold(const Json& object, ScriptStep& step) const {
    if (!object.contains("hold")) return;
    const std::string keys = string(object["hold"], "hold");
    step.ctrl = keys == "Ctrl" || keys == "Ctrl+Shift";
    step.shift = keys == "Shift" || keys == "Ctrl+Shift";
    if (!step.ctrl && !step.shift) fail("hold must be Ctrl, Shift or Ctrl+Shift");
  }

  ScriptStep parse(const Json& object) const {
    if (!object.is_object() || object.empty()) fail("not an object with one action");
    ScriptStep step;
    if (object.contains("move")) {
      step.kind = ScriptStep::Kind::move;
      step.at = point(object["move"], "move");
    } else if (object.contains("click")) {
      step.kind = ScriptStep::Kind::click;
      step.at = point(object["click"], "click");
      step.button = button(object);
    } else if (object.contains("click_mm")) {
      step.kind = ScriptStep::Kind::clickMm;
      const Json& p = object["click_mm"];
      if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number())
        fail("click_mm must be [x, y, z] in mm");
      step.pointMm = {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()};
    } else if (object.contains("double_click")) {
      step.kind = ScriptStep::Kind::doubleClick;
      step.at = point(object["double_click"], "double_click");
    } else if (object.contains("drag")) {
      const Json& drag = object["drag"];
      if (!drag.is_object() || !drag.contains("from") || !drag.contains("to"))
        fail("drag needs \"from\" and \"to\"");
      step.kind = ScriptStep::Kind::drag;
      step.at = point(drag["from"], "drag from");
      step.to = point(drag["to"], "drag to");
      step.button = button(drag);
      if (drag.contains("steps")) step.steps = int(number(drag["steps"], "drag steps", 1, 1000));
      hold(drag, step);
    } else if (object.contains("press")) {
      step.kind = ScriptStep::Kind::press;
      step.at = point(object["press"], "press");
      step.button = button(object);
    } else if (object.contains("release")) {
      step.kind = ScriptStep::Kind::release;
      step.at = point(object["release"], "release");
      step.button = button(object);
    } else if (object.contains("wheel")) {
      const Json& wheel = object["wheel"];
      if (!wheel.is_object() || !wheel.contains("at")) fail("wheel needs \"at\"");
      step.kind = ScriptStep::Kind::wheel;
      step.at = point(wheel["at"], "wheel at");
      step.value = wheel.contains("delta") ? number(wheel["delta"], "wheel delta", -100, 100) : 1;
      hold(wheel, step);
    } else if (object.contains("key")) {
      step.kind = ScriptStep::Kind::key;
      step.text = string(object["key"], "key");
    } else if (object.contains("text")) {
      step.kind = ScriptStep::Kind::text;
      step.text = string(object["text"], "text");
    } else if (object.contains("wait_ms")) {
      step.kind = ScriptStep::Kind::waitMs;
      step.value = number(object["wait_ms"], "wait_ms", 0, 600000);
    } else if (object.contains("wait_level")) {
      step.kind = ScriptStep::Kind::waitLevel;
      const auto level = parseQuality(string(object["wait_level"], "wait_level"));
      if (!level) fail("wait_level must be fast, medium or high");
      step.level = *level;
    } else if (object.contains("screenshot")) {
      step.kind = ScriptStep::Kind::screenshot;
      step.text = string(object["screenshot"], "screenshot");
    } else if (object.contains("open")) {
      step.kind = ScriptStep::Kind::open;
      step.text = string(object["open"], "open");
    } else if (object.contains("state")) {
      step.kind = ScriptStep::Kind::state;
      step.text = string(object["state"], "state");
    } else {
      fail("unknown action " + quotedText(object.begin().key()));
    }
    return step;
  }
};

}  // namespace

std::vector<ScriptStep> parseScript(const std::string& text, const std::filesystem::path& source) {
  const Json json = parseJsonText(text, source);
  if (!json.is_array()) throw InputError(source, "a script is a JSON list of steps");
  // Every step draws frames (a few milliseconds each in software GL): bounded so that a script
  // ends within minutes, not hours.
  if (json.size() > kMaxScriptSteps)
    throw InputError(source, "has " + std::to_string(json.size()) + " steps; a script holds at most " +
                                 std::to_string(kMaxScriptSteps) + " (split it)");
  std::vector<ScriptStep> steps;
  double waitMs = 0;
  std::size_t dragMoves = 0;
  for (std::size_t n = 0; n < json.size(); ++n) {
    steps.push_back(StepParser{source, "step " + std::to_string(n + 1)}.parse(json[n]));
    if (steps.back().kind == ScriptStep::Kind::waitMs) waitMs += steps.back().value;
    if (steps.back().kind == ScriptStep::Kind::drag) dragMoves += std::size_t(steps.back().steps);
  }
  if (waitMs > kMaxScriptWaitMs)
    throw InputError(source, "waits " + std::to_string(std::int64_t(waitMs / 1000)) +
                                 " s in all; a script may wait at most " +
                                 std::to_string(std::int64_t(kMaxScriptWaitMs / 1000)) + " s");
  if (dragMoves > kMaxScriptSteps)
    throw InputError(source, "drags through " + std::to_string(dragMoves) +
                                 " mouse moves in all; a script holds at most " +
                                 std::to_string(kMaxScriptSteps));
  return steps;
}

std::vector<ScriptStep> loadScript(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return parseScript(text.str(), path);
}

}  // namespace angio
