#include "render/recipe_json.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/clip_interval.h"
#include "core/number_text.h"
#include "io/atomic_write.h"
#include "io/json_text.h"
#include "io/sampling_json.h"
#include "io/shown_text.h"
#include "io/input_error.h"
#include "io/tf_file.h"
#include "io/vessel_glyph_json.h"
#include "vessel/vessel_glyph_spec.h"

namespace angio {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

// "\"key\" has unknown value 'value'", the value shown on one line (control bytes escaped).
std::string unknownValue(const std::string& key, const std::string& value) {
  std::string message = "\"" + key + "\" has unknown value ";
  return message + quotedText(value);
}

constexpr int kSidecarVersion = 1;

// --- Writing --------------------------------------------------------------------------------

Json tfJson(const TransferFunction& tf) { return Json::parse(toJson(tf)); }

Json vesselGlyphJson(const VesselGlyphRecipe& vg) {
  Json json = {{"centerlines", vg.centerlines}};
  const Json settings = vesselGlyphSettingsJson(vg.settings);
  for (const auto& [key, value] : settings.items()) json[key] = value;
  json["focus_tf"] = tfJson(vg.focusTf);
  json["context_tf"] = tfJson(vg.contextTf);
  json["outside_tf"] = vg.outsideTf ? tfJson(*vg.outsideTf) : Json(nullptr);
  return json;
}

Json hybridJson(const HybridCprRecipe& hybrid) {
  Json json = {{"path", hybrid.path},
               {"transition_mm", hybrid.transitionMm},
               {"display", hybrid.grey ? "grey" : "tf"}};
  if (hybrid.grey) json["window"] = hybrid.grey->window, json["level"] = hybrid.grey->level;
  return json;
}

Json vectorJson(glm::dvec3 v) { return Json::array({v.x, v.y, v.z}); }

// Each part null when off (render/recipe_json.h).
// The window only when there is one, so sidecars of whole images stay as they were.
Json viewJson(const RenderParams& p) {
  Json view = {{"axis", toString(p.axis)}, {"angle_deg", p.angleDeg}};
  if (p.window)
    view["window"] = {{"left_mm", p.window->leftMm},
                      {"right_mm", p.window->rightMm},
                      {"bottom_mm", p.window->bottomMm},
                      {"top_mm", p.window->topMm}};
  return view;
}

Json clippingJson(const ViewClipping& c) {
  Json json = {{"crop", nullptr}, {"plane", nullptr}, {"slab", nullptr}};
  if (c.crop)
    json["crop"] = {{"min_mm", vectorJson(c.crop->minMm)}, {"max_mm", vectorJson(c.crop->maxMm)}};
  if (c.plane)
    json["plane"] = c.plane->facingViewer
                        ? Json{{"facing_viewer", true}, {"offset_mm", c.plane->offsetMm}}
                        : Json{{"facing_viewer", false},
                               {"point_mm", vectorJson(c.plane->pointMm)},
                               {"normal", vectorJson(c.plane->normal)}};
  if (c.slab) json["slab"] = {{"offset_mm", c.slab->offsetMm}, {"thickness_mm", c.slab->thicknessMm}};
  return json;
}

// --- Reading: every accessor names the key in its one-line error ----------------------------

struct Reader {
  const fs::path& source;

  const Json& at(const Json& object, const std::string& key, const std::string& where) const {
    if (!object.is_object()) throw InputError(source, where + " is not a JSON object");
    const auto found = object.find(key);
    if (found == object.end()) throw InputError(source, "missing \"" + where + key + "\"");
    return *found;
  }
  double number(const Json& object, const std::string& key, const std::string& where = "") const {
    const Json& value = at(object, key, where);
    if (!value.is_number() || !std::isfinite(value.get<double>()))
      throw InputError(source, "\"" + where + key + "\" is not a number: " + value.dump());
    return value.get<double>();
  }
  bool flag(const Json& object, const std::string& key, const std::string& where = "") const {
    const Json& value = at(object, key, where);
    if (!value.is_boolean()) throw InputError(source, "\"" + where + key + "\" is not true/false");
    return value.get<bool>();
  }
  std::string text(const Json& object, const std::string& key, const std::string& where = "") const {
    const Json& value = at(object, key, where);
    if (!value.is_string()) throw InputError(source, "\"" + where + key + "\" is not a string");
    return value.get<std::string>();
  }
  glm::dvec3 vector(const Json& object, const std::string& key, const std::string& where) const {
    const Json& value = at(object, key, where);
    if (!value.is_array() || value.size() != 3)
      throw InputError(source, "\"" + where + key + "\" is not a list of 3 numbers");
    glm::dvec3 v;
    for (int n = 0; n < 3; ++n) {
      if (!value[n].is_number() || !std::isfinite(value[n].get<double>()))
        throw InputError(source, "\"" + where + key + "\" is not a list of 3 numbers");
      v[n] = value[n].get<double>();
    }
    return v;
  }
  template <class Parse>
  auto choice(const Json& object, const std::string& key, Parse parse,
              const std::string& where = "") const {
    const std::string value = text(object, key, where);
    const auto parsed = parse(value);
    if (!parsed) throw InputError(source, unknownValue(where + key, value));
    return *parsed;
  }
  TransferFunction tf(const Json& object, const std::string& key, const std::string& where = "") const {
    const Json& value = at(object, key, where);
    try {
      return parseTransferFunction(value.dump(), source);
    } catch (const InputError& error) {
      throw InputError(source, "\"" + where + key + "\": " +
                                   std::string(error.what()).substr(source.string().size() + 2));
    }
  }
};

TubeRadius readRadius(const Reader& r, const Json& json, const std::string& where) {
  TubeRadius radius;
  radius.mode = r.choice(json, "radius_mode", parseRadiusMode, where);
  radius.value = r.number(json, "radius", where);
  radius.marginMm = r.number(json, "margin_mm", where);
  return radius;
}

void readContext(const Reader& r, const Json& json, VesselGlyphSettings& s) {
  const std::string where = "vessel_glyph.context.";
  s.context = r.choice(json, "shape", parseContextShape, where);
  s.slab.frontMm = r.number(json, "front_mm", where);
  s.slab.backMm = r.number(json, "back_mm", where);
  const Json& width = r.at(json, "half_width_mm", where);
  s.slab.halfWidthMm =
      width == "inf" ? std::numeric_limits<double>::infinity() : r.number(json, "half_width_mm", where);
  s.contextTube = readRadius(r, r.at(json, "tube", where), where + "tube.");
}

VesselGlyphRecipe readVesselGlyph(const Reader& r, const Json& json) {
  const std::string where = "vessel_glyph.";
  VesselGlyphRecipe vg;
  vg.centerlines = r.text(json, "centerlines", where);
  VesselGlyphSettings& s = vg.settings;
  s.focus = readRadius(r, r.at(json, "focus", where), where + "focus.");
  readContext(r, r.at(json, "context", where), s);
  s.cleft = r.flag(json, "cleft", where);
  s.halfVessel = r.flag(json, "half_vessel", where);
  s.unknownVesselRadiusMm = r.number(json, "unknown_vessel_radius_mm", where);
  s.simplifyToleranceMm = r.number(json, "simplify_tolerance_mm", where);
  if (const auto problem = settingsProblem(s)) throw InputError(r.source, *problem);
  vg.focusTf = r.tf(json, "focus_tf", where);
  vg.contextTf = r.tf(json, "context_tf", where);
  if (!r.at(json, "outside_tf", where).is_null()) vg.outsideTf = r.tf(json, "outside_tf", where);
  return vg;
}

HybridCprRecipe readHybrid(const Reader& r, const Json& json) {
  const std::string where = "hybrid_cpr.";
  HybridCprRecipe hybrid;
  hybrid.path = r.text(json, "path", where);
  hybrid.transitionMm = r.number(json, "transition_mm", where);
  if (hybrid.transitionMm < 0) throw InputError(r.source, "\"hybrid_cpr.transition_mm\" is negative");
  const std::string display = r.text(json, "display", where);
  if (display == "grey")
    hybrid.grey = WindowLevel{r.number(json, "window", where), r.number(json, "level", where)};
  else if (display != "tf") throw InputError(r.source, unknownValue("hybrid_cpr.display", display));
  return hybrid;
}

ClipPlane readPlane(const Reader& r, const Json& json) {
  const std::string where = "clipping.plane.";
  ClipPlane plane;
  plane.facingViewer = r.flag(json, "facing_viewer", where);
  if (plane.facingViewer) {
    plane.offsetMm = r.number(json, "offset_mm", where);
  } else {
    plane.pointMm = r.vector(json, "point_mm", where);
    plane.normal = r.vector(json, "normal", where);
  }
  return plane;
}

// Absent in sidecars written before clipping existed: nothing clipped.
ViewClipping readClipping(const Reader& r, const Json& json) {
  ViewClipping c;
  if (!json.contains("clipping")) return c;
  const Json& clipping = r.at(json, "clipping", "");
  const std::string where = "clipping.";
  if (const Json& crop = r.at(clipping, "crop", where); !crop.is_null())
    c.crop =
        CropBox{r.vector(crop, "min_mm", where + "crop."), r.vector(crop, "max_mm", where + "crop.")};
  if (const Json& plane = r.at(clipping, "plane", where); !plane.is_null())
    c.plane = readPlane(r, plane);
  if (const Json& slab = r.at(clipping, "slab", where); !slab.is_null())
    c.slab = ThickSlab{r.number(slab, "offset_mm", where + "slab."),
                       r.number(slab, "thickness_mm", where + "slab.")};
  if (const std::string problem = clippingProblem(c); !problem.empty())
    throw InputError(r.source, "\"clipping\": " + problem);
  return c;
}

// Absent (the whole image) in sidecars of unzoomed views and those written before windows existed.
std::optional<ImageWindow> readWindow(const Reader& r, const Json& view) {
  if (!view.contains("window")) return std::nullopt;
  const Json& json = r.at(view, "window", "view.");
  const std::string where = "view.window.";
  const ImageWindow window{r.number(json, "left_mm", where), r.number(json, "right_mm", where),
                           r.number(json, "bottom_mm", where), r.number(json, "top_mm", where)};
  if (const std::string problem = imageWindowProblem(window); !problem.empty())
    throw InputError(r.source, "\"view.window\": " + problem);
  return window;
}

RenderParams readParams(const Reader& r, const Json& json) {
  RenderParams p;
  const Json& view = r.at(json, "view", "");
  p.axis = r.choice(view, "axis", parseAxis, "view.");
  p.angleDeg = r.number(view, "angle_deg", "view.");
  p.window = readWindow(r, view);
  const Json& sampling = r.at(json, "sampling", "");
  p.sampling.isd = r.number(sampling, "isd", "sampling.");
  p.sampling.osd = r.number(sampling, "osd", "sampling.");
  p.sampling.filter = r.choice(sampling, "filter", parseFilter, "sampling.");
  p.sampling.ert = r.number(sampling, "ert", "sampling.");
  // Absent in sidecars from before pre-integration existed: those images were post-classified.
  if (sampling.contains("preintegrated"))
    p.sampling.preintegrated = r.flag(sampling, "preintegrated", "sampling.");
  if (sampling.contains("adaptive") && !sampling["adaptive"].is_null()) {
    const Json& adaptive = r.at(sampling, "adaptive", "sampling.");
    p.sampling.adaptive = AdaptiveIntegration{r.number(adaptive, "tolerance", "sampling.adaptive."),
                                              r.number(adaptive, "initial_step", "sampling.adaptive."),
                                              r.number(adaptive, "min_step", "sampling.adaptive.")};
  }
  // Absent in sidecars from before adaptive sampling existed.
  if (sampling.contains("adaptive_sampling") && !sampling["adaptive_sampling"].is_null()) {
    const Json& adaptive = r.at(sampling, "adaptive_sampling", "sampling.");
    const auto whole = [&](const char* key) {
      const double value = r.number(adaptive, key, "sampling.adaptive_sampling.");
      if (value != std::floor(value) || value < 0 || value > kMaxAdaptiveLevels)
        throw InputError(r.source, std::string("\"sampling.adaptive_sampling.") + key +
                                       "\" must be a whole number 0.." +
                                       std::to_string(kMaxAdaptiveLevels));
      return int(value);
    };
    p.sampling.adaptiveSampling =
        AdaptiveSampling{whole("levels"), whole("ray_levels"),
                         r.number(adaptive, "tolerance", "sampling.adaptive_sampling.")};
  }
  if (const std::string problem = samplingProblem(p.sampling); !problem.empty())
    throw InputError(r.source, "\"sampling\": " + problem);
  const Json& shading = r.at(json, "shading", "");
  p.shading.enabled = r.flag(shading, "enabled", "shading.");
  p.shading.ka = r.number(shading, "ka", "shading.");
  p.shading.kd = r.number(shading, "kd", "shading.");
  const std::string compositing = r.text(json, "compositing");
  if (compositing != "dvr" && compositing != "mip")
    throw InputError(r.source, unknownValue("compositing", compositing));
  p.compositing = compositing == "mip" ? Compositing::mip : Compositing::dvr;
  const Json& mip = r.at(json, "mip", "");
  p.mip.window = r.number(mip, "window", "mip.");
  p.mip.level = r.number(mip, "level", "mip.");
  p.clipping = readClipping(r, json);
  return p;
}

// The view, sampling and shading (or MIP window) of a plain render.
ImageMetadata viewMetadata(const RenderRecipe& s) {
  const RenderParams& p = s.params;
  ImageMetadata metadata{
      {"version", ANGIORAY_VERSION},
      {"dataset", s.dataset},
      {"axis", toString(p.axis)},
      {"angle_deg", numberText(p.angleDeg)},
      {"mode", p.compositing == Compositing::mip ? "mip" : "dvr"},
      {"isd", numberText(p.sampling.isd)},
      {"osd", numberText(p.sampling.osd)},
      {"filter", toString(p.sampling.filter)},
      {"ert", numberText(p.sampling.ert)},
      {"classification", p.sampling.preintegrated ? "pre-integrated" : "post"},
      {"integration", p.sampling.adaptive
                          ? "adaptive, tolerance " + numberText(p.sampling.adaptive->tolerance) +
                                ", initial step " + numberText(p.sampling.adaptive->initialStep)
                          : "samples every osd"},
      {"adaptive_sampling", p.sampling.adaptiveSampling
                                ? std::to_string(p.sampling.adaptiveSampling->levels) + " levels, " +
                                      std::to_string(p.sampling.adaptiveSampling->rayLevels) +
                                      " along rays, tolerance " +
                                      numberText(p.sampling.adaptiveSampling->tolerance)
                                : "off"},
  };
  if (s.quality) metadata["quality"] = toString(*s.quality);
  if (p.compositing == Compositing::mip) {
    metadata["mip_window"] = numberText(p.mip.window);
    metadata["mip_level"] = numberText(p.mip.level);
  } else {
    metadata["transfer_function"] = s.tf.name;
    metadata["shading"] = p.shading.enabled ? "on" : "off";
    metadata["ka"] = numberText(p.shading.ka);
    metadata["kd"] = numberText(p.shading.kd);
  }
  return metadata;
}

std::string vectorText(glm::dvec3 v) {
  return numberText(v.x) + "," + numberText(v.y) + "," + numberText(v.z);
}

// The clipping in the words of the `render` flags (--crop, --clip, --clip-facing, --slab).
void addClippingMetadata(const ViewClipping& c, ImageMetadata& metadata) {
  if (c.crop) {
    const CropBox& box = *c.crop;
    std::string text;
    for (int axis = 0; axis < 3; ++axis) {
      if (axis) text += ',';
      text += numberText(box.minMm[axis]);
      text += ',';
      text += numberText(box.maxMm[axis]);
    }
    metadata["crop_mm"] = text;
  }
  if (c.plane)
    metadata["clip"] = c.plane->facingViewer
                           ? "facing viewer, offset " + numberText(c.plane->offsetMm) + " mm"
                           : vectorText(c.plane->pointMm) + "," + vectorText(c.plane->normal);
  if (c.slab) metadata["slab_mm"] = numberText(c.slab->offsetMm) + "," + numberText(c.slab->thicknessMm);
}

}  // namespace

fs::path sidecarPathFor(const fs::path& image) { return fs::path(image.string() + ".json"); }

std::string renderSidecarJson(const RenderRecipe& s) {
  const RenderParams& p = s.params;
  Json json = {
      {"angioray_render_sidecar", kSidecarVersion},
      {"angioray_version", ANGIORAY_VERSION},
      {"image", s.image},
      {"dataset", s.dataset},
      {"labels", s.labels},
      {"quality", s.quality ? Json(toString(*s.quality)) : Json(nullptr)},
      {"raycaster", s.raycaster == Raycaster::reference ? "reference" : "fast"},
      {"view", viewJson(p)},
      {"sampling", samplingJson(p.sampling)},
      {"shading", {{"enabled", p.shading.enabled}, {"ka", p.shading.ka}, {"kd", p.shading.kd}}},
      {"compositing", p.compositing == Compositing::mip ? "mip" : "dvr"},
      {"mip", {{"window", p.mip.window}, {"level", p.mip.level}}},
      {"clipping", clippingJson(p.clipping)},
      {"tf", tfJson(s.tf)},
      {"vessel_glyph", s.vesselGlyph ? vesselGlyphJson(*s.vesselGlyph) : Json(nullptr)},
      {"hybrid_cpr", s.hybrid ? hybridJson(*s.hybrid) : Json(nullptr)},
  };
  return json.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

void saveRenderSidecar(const RenderRecipe& sidecar, const fs::path& file) {
  const std::string text = renderSidecarJson(sidecar);
  writeAtomically(file, [&](const fs::path& temp) {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw InputError(file, "cannot write the render sidecar");
  });
}

RenderRecipe parseRenderSidecar(const std::string& text, const fs::path& source) {
  const Json json = parseJsonText(text, source);
  const Reader r{source};
  if (!json.is_object() || !json.contains("angioray_render_sidecar"))
    throw InputError(source, "not an angioray render sidecar (no \"angioray_render_sidecar\" key)");
  if (r.number(json, "angioray_render_sidecar") != kSidecarVersion)
    throw InputError(source, "unsupported sidecar version " + json["angioray_render_sidecar"].dump());
  RenderRecipe s;
  s.image = r.text(json, "image");
  s.dataset = r.text(json, "dataset");
  s.labels = r.text(json, "labels");
  if (!r.at(json, "quality", "").is_null()) s.quality = r.choice(json, "quality", parseQuality);
  const std::string raycaster = r.text(json, "raycaster");
  if (raycaster != "fast" && raycaster != "reference")
    throw InputError(source, unknownValue("raycaster", raycaster));
  s.raycaster = raycaster == "reference" ? Raycaster::reference : Raycaster::fast;
  s.params = readParams(r, json);
  s.tf = r.tf(json, "tf");
  if (!r.at(json, "vessel_glyph", "").is_null())
    s.vesselGlyph = readVesselGlyph(r, json["vessel_glyph"]);
  if (!r.at(json, "hybrid_cpr", "").is_null()) {
    if (!s.vesselGlyph) throw InputError(source, "\"hybrid_cpr\" needs \"vessel_glyph\"");
    s.hybrid = readHybrid(r, json["hybrid_cpr"]);
  }
  return s;
}

RenderRecipe loadRenderSidecar(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw InputError(file,
                     fs::exists(file) ? "cannot read the render sidecar" : "no such render sidecar");
  std::ostringstream text;
  text << in.rdbuf();
  return parseRenderSidecar(text.str(), file);
}

ImageMetadata renderSidecarMetadata(const RenderRecipe& s) {
  ImageMetadata metadata = viewMetadata(s);
  metadata["raycaster"] = s.raycaster == Raycaster::reference ? "reference" : "fast";
  if (!s.labels.empty()) metadata["labels"] = s.labels;
  addClippingMetadata(s.params.clipping, metadata);
  if (s.vesselGlyph) {
    const VesselGlyphRecipe& vg = *s.vesselGlyph;
    metadata.erase("transfer_function");
    metadata["centerlines"] = vg.centerlines;
    metadata["vg_focus"] = focusSpecText(vg.settings.focus);
    metadata["vg_context"] = contextSpecText(vg.settings);
    metadata["vg_outside"] = vg.outsideTf ? "tf " + vg.outsideTf->name : "clip";
    metadata["vg_cleft"] = vg.settings.cleft ? "on" : "off";
    metadata["vg_half_vessel"] = vg.settings.halfVessel ? "on" : "off";
    metadata["focus_tf"] = vg.focusTf.name;
    metadata["context_tf"] = vg.contextTf.name;
  }
  if (s.hybrid) {
    metadata["hybrid_cpr_path"] = s.hybrid->path;
    metadata["hybrid_transition_mm"] = numberText(s.hybrid->transitionMm);
    metadata["hybrid_cpr_display"] = s.hybrid->grey ? "window " + numberText(s.hybrid->grey->window) +
                                                          " level " + numberText(s.hybrid->grey->level)
                                                    : "tf " + s.vesselGlyph->focusTf.name;
  }
  return metadata;
}

}  // namespace angio
