#include "io/tf_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/atomic_write.h"
#include "io/json_text.h"
#include "io/input_error.h"
#include "io/lowercase.h"

#ifndef ANGIORAY_PRESET_DIR
#define ANGIORAY_PRESET_DIR "presets"
#endif

namespace angio {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

namespace {

constexpr double kMinHu = huOfDensity(0);
constexpr double kMaxHu = huOfDensity(kDensityLevels - 1);

std::string formatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// --- Loading --------------------------------------------------------------------------------

// A JSON value that must be a finite number (strings such as "NaN", null and booleans are
// rejected). JSON has no NaN or infinity and the parser rejects 1e999, so the finiteness check is
// a guard for JSON built in memory.
double requireNumber(const Json& value, const fs::path& source, const std::string& what) {
  if (!value.is_number()) throw InputError(source, what + " is not a number: " + value.dump());
  const double number = value.get<double>();
  if (!std::isfinite(number)) throw InputError(source, what + " is not finite");
  return number;
}

double requireInRange(const Json& value, double lo, double hi, const fs::path& source,
                      const std::string& what) {
  const double number = requireNumber(value, source, what);
  if (number < lo || number > hi) {
    throw InputError(source, what + " " + formatNumber(number) + " outside [" + formatNumber(lo) + ", " +
                                 formatNumber(hi) + "]");
  }
  return number;
}

const Json& requireKey(const Json& object, const char* key, const fs::path& source,
                       const std::string& where) {
  const auto found = object.find(key);
  if (found == object.end()) throw InputError(source, where + " has no \"" + key + "\"");
  return *found;
}

// Points are numbered from 1 in messages, in file order.
ControlPoint parsePoint(const Json& point, int number, const fs::path& source,
                        const std::string& owner = "") {
  const std::string where = owner + "point " + std::to_string(number);
  if (!point.is_object()) throw InputError(source, where + " is not an object");
  ControlPoint parsed;
  parsed.hu =
      requireInRange(requireKey(point, "hu", source, where), kMinHu, kMaxHu, source, where + ": hu");
  const Json& color = requireKey(point, "color", source, where);
  if (!color.is_array() || color.size() != 3)
    throw InputError(source, where + ": color is not an array of 3 numbers");
  for (int c = 0; c < 3; ++c) {
    parsed.color[c] =
        float(requireInRange(color[c], 0, 1, source, where + ": color[" + std::to_string(c) + "]"));
  }
  parsed.opacity =
      requireInRange(requireKey(point, "opacity", source, where), 0, 1, source, where + ": opacity");
  return parsed;
}

void parseMip(const Json& mip, const fs::path& source, TransferFunction& tf) {
  if (!mip.is_object()) throw InputError(source, "\"mip\" is not an object");
  if (mip.contains("window")) {
    tf.mipWindow = requireNumber(mip["window"], source, "mip window");
    if (tf.mipWindow <= 0) throw InputError(source, "mip window must be > 0");
  }
  if (mip.contains("level")) tf.mipLevel = requireNumber(mip["level"], source, "mip level");
}

void parseModulators(const Json& modulators, const fs::path& source, TransferFunction& tf) {
  if (!modulators.is_object()) throw InputError(source, "\"modulators\" is not an object");
  if (modulators.contains("opacity_scale")) {
    tf.modulators.opacityScale =
        requireNumber(modulators["opacity_scale"], source, "modulators opacity_scale");
    if (tf.modulators.opacityScale < 0)
      throw InputError(source, "modulators opacity_scale must be >= 0");
  }
  if (modulators.contains("hu_shift"))
    tf.modulators.huShift = requireNumber(modulators["hu_shift"], source, "modulators hu_shift");
}

std::optional<LabelMode> parseLabelMode(const std::string& text) {
  if (text == "main") return LabelMode::main;
  if (text == "hidden") return LabelMode::hidden;
  if (text == "tf") return LabelMode::tf;
  return std::nullopt;
}

const char* labelModeName(LabelMode mode) {
  switch (mode) {
    case LabelMode::main: return "main";
    case LabelMode::hidden: return "hidden";
    case LabelMode::tf: return "tf";
  }
  return "main";
}

glm::vec3 parseColor(const Json& color, const fs::path& source, const std::string& where) {
  if (!color.is_array() || color.size() != 3)
    throw InputError(source, where + ": color is not an array of 3 numbers");
  glm::vec3 parsed;
  for (int c = 0; c < 3; ++c)
    parsed[c] =
        float(requireInRange(color[c], 0, 1, source, where + ": color[" + std::to_string(c) + "]"));
  return parsed;
}

// Rendering model, "Labels": {"label": 1..15, "name", "mode": main | hidden | tf, "points" (tf),
// "color" (optional)}.
LabelStyle parseLabelStyle(const Json& entry, const fs::path& source) {
  if (!entry.is_object()) throw InputError(source, "a \"labels\" entry is not an object");
  const Json& labelValue = requireKey(entry, "label", source, "a \"labels\" entry");
  const double label = requireInRange(labelValue, 1, kMaxLabel, source, "label");
  if (label != std::floor(label))
    throw InputError(source, "label " + labelValue.dump() + " is not an integer");
  LabelStyle style;
  style.label = int(label);
  const std::string where = "label " + std::to_string(style.label);
  if (entry.contains("name")) {
    if (!entry["name"].is_string()) throw InputError(source, where + ": \"name\" is not a string");
    style.name = entry["name"].get<std::string>();
  }
  const Json& mode = requireKey(entry, "mode", source, where);
  const auto parsedMode = mode.is_string() ? parseLabelMode(mode.get<std::string>()) : std::nullopt;
  if (!parsedMode)
    throw InputError(source, where + ": mode " + mode.dump() + " is not main, hidden or tf");
  style.mode = *parsedMode;
  if (entry.contains("color")) style.color = parseColor(entry["color"], source, where);
  if (entry.contains("points")) {
    const Json& points = entry["points"];
    if (!points.is_array()) throw InputError(source, where + ": \"points\" is not an array");
    for (std::size_t i = 0; i < points.size(); ++i)
      style.points.push_back(parsePoint(points[i], int(i) + 1, source, where + ": "));
    std::stable_sort(style.points.begin(), style.points.end(),
                     [](const ControlPoint& a, const ControlPoint& b) { return a.hu < b.hu; });
  }
  if (style.mode == LabelMode::tf && style.points.empty())
    throw InputError(source, where + ": mode tf needs \"points\"");
  return style;
}

std::vector<LabelStyle> parseLabelStyles(const Json& labels, const fs::path& source) {
  if (!labels.is_array()) throw InputError(source, "\"labels\" is not an array");
  std::vector<LabelStyle> styles;
  for (const Json& entry : labels) {
    LabelStyle style = parseLabelStyle(entry, source);
    for (const LabelStyle& earlier : styles)
      if (earlier.label == style.label)
        throw InputError(source, "label " + std::to_string(style.label) + " is listed twice");
    styles.push_back(std::move(style));
  }
  return styles;
}

// --- Saving ---------------------------------------------------------------------------------

// Colors are floats: written with the shortest decimal that reads back as the same float
// (0.6f as 0.6, not 0.6000000238418579), so files stay readable and round trips stay exact.
double shortestDecimal(float value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::strtod(std::string(buffer, end).c_str(), nullptr);
}

std::string dumpJson(const OrderedJson& value, int indent = -1) {
  // Invalid UTF-8 in a name is replaced rather than throwing halfway through a save.
  return value.dump(indent, ' ', false, Json::error_handler_t::replace);
}

OrderedJson colorJson(glm::vec3 color) {
  return {shortestDecimal(color.r), shortestDecimal(color.g), shortestDecimal(color.b)};
}

OrderedJson pointJson(const ControlPoint& point) {
  OrderedJson json;
  json["hu"] = point.hu;
  json["color"] = colorJson(point.color);
  json["opacity"] = point.opacity;
  return json;
}

OrderedJson labelStyleJson(const LabelStyle& style) {
  OrderedJson json;
  json["label"] = style.label;
  json["name"] = style.name;
  json["mode"] = labelModeName(style.mode);
  json["color"] = colorJson(style.color);
  if (!style.points.empty()) {
    json["points"] = OrderedJson::array();
    for (const ControlPoint& point : style.points) json["points"].push_back(pointJson(point));
  }
  return json;
}

// --- Presets --------------------------------------------------------------------------------

fs::path presetDirectory() {
  if (const char* fromEnvironment = std::getenv("ANGIORAY_PRESET_DIR");
      fromEnvironment != nullptr && *fromEnvironment != '\0') {
    return fromEnvironment;
  }
  std::error_code error;
  const fs::path besideExecutable = fs::read_symlink("/proc/self/exe", error).parent_path() / "presets";
  if (!error && fs::is_directory(besideExecutable, error)) return besideExecutable;
  return ANGIORAY_PRESET_DIR;
}

std::string presetIdList(const std::vector<Preset>& presets) {
  std::string list;
  for (const Preset& preset : presets) list += (list.empty() ? "" : ", ") + preset.id;
  return list.empty() ? "(none found)" : list;
}

}  // namespace

TransferFunction parseTransferFunction(const std::string& text, const fs::path& source) {
  const Json json = parseJsonText(text, source);
  if (!json.is_object()) throw InputError(source, "not a transfer function (expected a JSON object)");

  TransferFunction tf;
  tf.name = source.stem().string();
  if (json.contains("name")) {
    if (!json["name"].is_string()) throw InputError(source, "\"name\" is not a string");
    tf.name = json["name"].get<std::string>();
  }
  if (!json.contains("points")) throw InputError(source, "has no \"points\"");
  const Json& points = json["points"];
  if (!points.is_array()) throw InputError(source, "\"points\" is not an array");
  if (points.empty()) throw InputError(source, "\"points\" is empty");
  for (std::size_t i = 0; i < points.size(); ++i)
    tf.points.push_back(parsePoint(points[i], int(i) + 1, source));
  sortPoints(tf);

  if (json.contains("mip")) parseMip(json["mip"], source, tf);
  if (json.contains("modulators")) parseModulators(json["modulators"], source, tf);
  if (json.contains("labels")) tf.labels = parseLabelStyles(json["labels"], source);
  // "description" and "mode" are for people and the UI; a TransferFunction does not keep them.
  return tf;
}

TransferFunction loadTransferFunction(const fs::path& path) {
  std::error_code error;
  if (!fs::exists(path, error)) throw InputError(path, "no such file");
  if (fs::is_directory(path, error)) throw InputError(path, "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in || in.bad()) throw InputError(path, "cannot read the file");
  return parseTransferFunction(text.str(), path);
}

std::string toJson(const TransferFunction& tf) {
  // One point per line, like the shipped presets, rather than dump(2)'s one number per line.
  std::string out = "{\n  \"name\": " + dumpJson(OrderedJson(tf.name)) + ",\n  \"points\": [\n";
  for (std::size_t i = 0; i < tf.points.size(); ++i) {
    out += "    " + dumpJson(pointJson(tf.points[i])) + (i + 1 < tf.points.size() ? ",\n" : "\n");
  }
  out += "  ],\n";
  const OrderedJson mip = {{"window", tf.mipWindow}, {"level", tf.mipLevel}};
  const OrderedJson modulators = {{"opacity_scale", tf.modulators.opacityScale},
                                  {"hu_shift", tf.modulators.huShift}};
  out += "  \"mip\": " + dumpJson(mip) + ",\n";
  out += "  \"modulators\": " + dumpJson(modulators);
  // Written only when there are any, so files without labels stay as they were.
  if (!tf.labels.empty()) {
    out += ",\n  \"labels\": [\n";
    for (std::size_t i = 0; i < tf.labels.size(); ++i)
      out += "    " + dumpJson(labelStyleJson(tf.labels[i])) + (i + 1 < tf.labels.size() ? ",\n" : "\n");
    out += "  ]";
  }
  out += "\n}\n";
  return out;
}

void saveTransferFunction(const TransferFunction& tf, const fs::path& path) {
  writeBytesAtomically(path, toJson(tf));
}

std::vector<Preset> listPresets() {
  std::vector<Preset> presets;
  std::error_code error;
  for (fs::directory_iterator it(presetDirectory(), error), end; !error && it != end;
       it.increment(error)) {
    const fs::path& file = it->path();
    if (file.extension() == ".json" && it->is_regular_file(error))
      presets.push_back({file.stem().string(), file});
  }
  std::sort(presets.begin(), presets.end(),
            [](const Preset& a, const Preset& b) { return a.id < b.id; });
  return presets;
}

TransferFunction loadPresetOrFile(const std::string& presetOrPath) {
  const std::vector<Preset> presets = listPresets();
  for (const Preset& preset : presets) {
    if (preset.id == presetOrPath) return loadTransferFunction(preset.file);
  }
  const std::string wantedName = lowercase(presetOrPath);
  for (const Preset& preset : presets) {
    try {
      TransferFunction tf = loadTransferFunction(preset.file);
      if (lowercase(tf.name) == wantedName) return tf;
    } catch (const InputError&) {
      // A broken preset cannot match by name; it must not hide a valid file argument either.
    }
  }
  std::error_code error;
  if (!presetOrPath.empty() && fs::exists(presetOrPath, error))
    return loadTransferFunction(presetOrPath);
  throw InputError(presetOrPath, "no such preset or file; presets: " + presetIdList(presets));
}

}  // namespace angio
