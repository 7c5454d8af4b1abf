#include "io/vessel_glyph_json.h"

#include <cmath>

namespace angio {

using Json = nlohmann::ordered_json;

namespace {

Json radiusJson(const TubeRadius& radius) {
  return {{"radius_mode", radiusModeName(radius.mode)},
          {"radius", radius.value},
          {"margin_mm", radius.marginMm}};
}

}  // namespace

const char* radiusModeName(RadiusMode mode) {
  return mode == RadiusMode::vesselFactor ? "factor" : "mm";
}

std::optional<RadiusMode> parseRadiusMode(const std::string& name) {
  if (name == "factor") return RadiusMode::vesselFactor;
  if (name == "mm") return RadiusMode::constant;
  return std::nullopt;
}

const char* contextShapeName(ContextShape shape) {
  switch (shape) {
    case ContextShape::none: return "none";
    case ContextShape::tube: return "tube";
    case ContextShape::slab: break;
  }
  return "slab";
}

std::optional<ContextShape> parseContextShape(const std::string& name) {
  if (name == "none") return ContextShape::none;
  if (name == "slab") return ContextShape::slab;
  if (name == "tube") return ContextShape::tube;
  return std::nullopt;
}

Json vesselGlyphSettingsJson(const VesselGlyphSettings& s) {
  Json context = {
      {"shape", contextShapeName(s.context)}, {"front_mm", s.slab.frontMm}, {"back_mm", s.slab.backMm}};
  if (std::isinf(s.slab.halfWidthMm)) context["half_width_mm"] = "inf";
  else context["half_width_mm"] = s.slab.halfWidthMm;
  context["tube"] = radiusJson(s.contextTube);
  return {{"focus", radiusJson(s.focus)},
          {"context", context},
          {"cleft", s.cleft},
          {"half_vessel", s.halfVessel},
          {"unknown_vessel_radius_mm", s.unknownVesselRadiusMm},
          {"simplify_tolerance_mm", s.simplifyToleranceMm}};
}

}  // namespace angio
