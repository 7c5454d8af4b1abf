#include "vessel/vessel_glyph_spec.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <vector>

#include "core/number_text.h"

namespace angio {

namespace {

constexpr const char* kFocusForm =
    "circle:radius=R (R in mm, e.g. 3 or 3mm, or a factor of the "
    "vessel radius, e.g. 2.0x)";
constexpr const char* kContextForm = "slab:front=MM,back=MM[,width=MM|inf], tube:radius=R or none";

// A spec split into its shape and key=value parameters.
struct SpecParts {
  std::string shape;
  std::map<std::string, std::string> values;
};

std::string quoted(const std::string& text) {
  std::string out = "'";
  out += text;
  out += "'";
  return out;
}

[[noreturn]] void fail(const std::string& option, const std::string& spec, const std::string& problem,
                       const char* form) {
  throw std::invalid_argument(option + " '" + spec + "': " + problem + "; expected " + form);
}

SpecParts splitSpec(const std::string& option, const std::string& spec, const char* form) {
  SpecParts parts;
  const std::size_t colon = spec.find(':');
  parts.shape = spec.substr(0, colon);
  if (colon == std::string::npos) return parts;
  std::size_t start = colon + 1;
  while (start <= spec.size()) {
    const std::size_t comma = std::min(spec.find(',', start), spec.size());
    const std::string item = spec.substr(start, comma - start);
    const std::size_t equals = item.find('=');
    if (equals == std::string::npos || equals == 0)
      fail(option, spec, quoted(item) + " is not key=value", form);
    if (!parts.values.emplace(item.substr(0, equals), item.substr(equals + 1)).second)
      fail(option, spec, quoted(item.substr(0, equals)) + " given twice", form);
    start = comma + 1;
  }
  return parts;
}

void requireKeys(const std::string& option, const std::string& spec, const SpecParts& parts,
                 const std::vector<std::string>& required, const std::vector<std::string>& optional,
                 const char* form) {
  for (const auto& [key, value] : parts.values) {
    bool known = false;
    for (const auto* list : {&required, &optional})
      for (const std::string& name : *list) known = known || name == key;
    if (!known) fail(option, spec, "unknown key '" + key + "'", form);
  }
  for (const std::string& key : required)
    if (!parts.values.count(key)) fail(option, spec, "missing '" + key + "'", form);
}

// A finite number >= 0 in mm ("20", "20mm"), or infinity where allowed ("inf").
double parseMm(const std::string& option, const std::string& spec, const std::string& key,
               std::string text, bool allowInfinity, const char* form) {
  if (allowInfinity && text == "inf") return std::numeric_limits<double>::infinity();
  if (text.size() > 2 && text.ends_with("mm")) text.resize(text.size() - 2);
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value) || value < 0)
    fail(option, spec, key + " '" + text + "' is not a number >= 0", form);
  return value;
}

// "2.0x" -> a factor of the vessel radius, "3" / "3mm" -> a constant in mm; must be > 0.
TubeRadius parseRadius(const std::string& option, const std::string& spec, const std::string& text,
                       const char* form) {
  TubeRadius radius;
  const bool factor = !text.empty() && text.back() == 'x';
  radius.mode = factor ? RadiusMode::vesselFactor : RadiusMode::constant;
  radius.value =
      parseMm(option, spec, "radius", factor ? text.substr(0, text.size() - 1) : text, false, form);
  if (radius.value <= 0) fail(option, spec, "radius must be > 0", form);
  return radius;
}

std::string radiusText(const TubeRadius& radius) {
  return numberText(radius.value) + (radius.mode == RadiusMode::vesselFactor ? "x" : "mm");
}

}  // namespace

TubeRadius parseFocusSpec(const std::string& spec) {
  const std::string option = "--vg-focus";
  const SpecParts parts = splitSpec(option, spec, kFocusForm);
  if (parts.shape != "circle") fail(option, spec, "unknown shape '" + parts.shape + "'", kFocusForm);
  requireKeys(option, spec, parts, {"radius"}, {}, kFocusForm);
  return parseRadius(option, spec, parts.values.at("radius"), kFocusForm);
}

void parseContextSpec(const std::string& spec, VesselGlyphSettings& settings) {
  const std::string option = "--vg-context";
  const SpecParts parts = splitSpec(option, spec, kContextForm);
  if (parts.shape == "none") {
    requireKeys(option, spec, parts, {}, {}, kContextForm);
    settings.context = ContextShape::none;
  } else if (parts.shape == "slab") {
    requireKeys(option, spec, parts, {"front", "back"}, {"width"}, kContextForm);
    SlabContext slab;
    slab.frontMm = parseMm(option, spec, "front", parts.values.at("front"), false, kContextForm);
    slab.backMm = parseMm(option, spec, "back", parts.values.at("back"), false, kContextForm);
    if (parts.values.count("width"))
      slab.halfWidthMm = parseMm(option, spec, "width", parts.values.at("width"), true, kContextForm);
    settings.context = ContextShape::slab;
    settings.slab = slab;
  } else if (parts.shape == "tube") {
    requireKeys(option, spec, parts, {"radius"}, {}, kContextForm);
    settings.context = ContextShape::tube;
    settings.contextTube = parseRadius(option, spec, parts.values.at("radius"), kContextForm);
  } else {
    fail(option, spec, "unknown shape '" + parts.shape + "'", kContextForm);
  }
}

std::string focusSpecText(const TubeRadius& focus) { return "circle:radius=" + radiusText(focus); }

std::string contextSpecText(const VesselGlyphSettings& settings) {
  switch (settings.context) {
    case ContextShape::none: return "none";
    case ContextShape::tube: return "tube:radius=" + radiusText(settings.contextTube);
    case ContextShape::slab: break;
  }
  const SlabContext& slab = settings.slab;
  return "slab:front=" + numberText(slab.frontMm) + ",back=" + numberText(slab.backMm) +
         ",width=" + (std::isinf(slab.halfWidthMm) ? std::string("inf") : numberText(slab.halfWidthMm));
}

}  // namespace angio
