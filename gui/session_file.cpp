#include "gui/session_file.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "io/atomic_write.h"
#include "io/json_text.h"
#include "io/sampling_json.h"
#include "io/input_error.h"
#include "io/tf_file.h"
#include "io/vessel_glyph_json.h"
#include "gui/cpr_pane.h"
#include "gui/session_vessels.h"

namespace angio {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

constexpr const char* kFormat = "angioray-session";
constexpr int kVersion = 1;

constexpr double kMaxTransitionMm = 100;

Json cprJson(const CprState& cpr) {
  return {{"shown", cpr.shown},
          {"mode", toString(cpr.mode)},
          {"path", cpr.path},
          {"colouring", cprColoringName(cpr.coloring)},
          {"window", cpr.window.window},
          {"level", cpr.window.level},
          {"width_mm", cpr.widthMm},
          {"zoom", cpr.zoom},
          {"pan_px", {cpr.panPx.x, cpr.panPx.y}},
          {"hybrid", cpr.hybrid},
          {"transition_mm", cpr.transitionMm},
          {"cursor", cpr.cursor ? Json{{"path", cpr.cursor->path}, {"arc_mm", cpr.cursor->arcMm}}
                                : Json(nullptr)}};
}

Json vesselGlyphJson(const VesselGlyphState& vg) {
  const auto tfOrNull = [](const TransferFunction& tf) {
    return tf.points.empty() ? Json(nullptr) : Json::parse(toJson(tf));
  };
  Json json = {{"centerlines", vg.centerlines},
               {"centerlines_absolute", vg.centerlinesAbsolute},
               {"enabled", vg.enabled},
               {"overlay", vg.overlay}};
  json.update(Json::parse(vesselGlyphSettingsJson(vg.settings).dump()));
  json["outside"] = vg.outsideRendered ? "main-tf" : "clip";
  json["focus_follows_main_tf"] = vg.focusFollowsMain;
  json["context_follows_main_tf"] = vg.contextFollowsMain;
  json["focus_tf"] = tfOrNull(vg.focusTf);
  json["context_tf"] = tfOrNull(vg.contextTf);
  json["focus_preset"] = vg.focusPreset;
  json["context_preset"] = vg.contextPreset;
  return json;
}

Json vectorJson(glm::dvec3 v) { return {v.x, v.y, v.z}; }

Json clipJson(const ClipState& clip) {
  return {{"crop_on", clip.cropOn},
          {"crop_min_mm", vectorJson(clip.crop.minMm)},
          {"crop_max_mm", vectorJson(clip.crop.maxMm)},
          {"plane_on", clip.planeOn},
          {"facing_viewer", clip.facingViewer},
          {"normal", vectorJson(clipNormalOf(clip))},
          {"plane_offset_mm", clip.planeOffsetMm},
          {"slab_on", clip.slabOn},
          {"slab_offset_mm", clip.slab.offsetMm},
          {"slab_thickness_mm", clip.slab.thicknessMm}};
}

// The slice view; the cursor only where the user put it (null: the volume's centre).
Json slicePanesJson(const std::array<SlicePaneView, 3>& panes) {
  Json json = Json::object();
  for (int o = 0; o < 3; ++o)
    json[sliceOrientationName(SliceOrientation(o))] = {{"zoom", panes[o].zoom},
                                                       {"pan_px", {panes[o].panPx.x, panes[o].panPx.y}}};
  return json;
}

Json slicesJson(const SliceViewState& slices) {
  return {{"shown", slices.shown},
          {"window", slices.windowLevel.window},
          {"level", slices.windowLevel.level},
          {"cursor_mm", slices.cursorMm ? vectorJson(*slices.cursorMm) : Json(nullptr)},
          {"panes", slicePanesJson(slices.panes)}};
}

// Reads one session file: every key optional (defaults stay), every present key checked.
struct SessionReader {
  const fs::path& source;
  std::string where = "";       // the keys' section in messages, e.g. "vessel_glyph.focus."
  Json empty = Json::object();  // a missing section reads as this

  [[noreturn]] void fail(const std::string& problem) const { throw InputError(source, problem); }
  SessionReader in(const char* key) const { return {source, where + key + "."}; }

  double number(const Json& object, const char* key, double lo, double hi, double fallback) const {
    if (!object.contains(key)) return fallback;
    const Json& value = object[key];
    if (!value.is_number()) fail(where + key + " is not a number");
    const double n = value.get<double>();
    if (!std::isfinite(n) || n < lo || n > hi)
      fail(where + key + " " + value.dump() + " is out of range");
    return n;
  }
  bool flag(const Json& object, const char* key, bool fallback) const {
    if (!object.contains(key)) return fallback;
    if (!object[key].is_boolean()) fail(where + key + " is not true or false");
    return object[key].get<bool>();
  }
  std::string text(const Json& object, const char* key) const {
    if (!object.contains(key)) return "";
    if (!object[key].is_string()) fail(where + key + " is not a string");
    return object[key].get<std::string>();
  }
  const Json& section(const Json& object, const char* key) const {
    if (!object.contains(key)) return empty;
    if (!object[key].is_object()) fail(where + key + " is not an object");
    return object[key];
  }
  // A name from a list (parse gives none for an unknown one); `names` says which there are.
  template <class Parse>
  auto choice(const Json& object, const char* key, Parse parse, decltype(parse("")) fallback,
              const char* names) const {
    if (!object.contains(key)) return fallback;
    const auto parsed = parse(text(object, key));
    if (!parsed) fail(where + key + " is not " + names);
    return parsed;
  }
  // A TF in full, or null / missing: `fallback`.
  TransferFunction tf(const Json& object, const char* key, const TransferFunction& fallback) const {
    if (!object.contains(key) || object[key].is_null()) return fallback;
    if (!object[key].is_object()) fail(where + key + " is not a transfer function (an object) or null");
    try {
      return parseTransferFunction(object[key].dump(), source);
    } catch (const InputError& error) {  // "<source>: <problem>"
      fail(where + key + ": " + std::string(error.what()).substr(source.string().size() + 2));
    }
  }

  TubeRadius radius(const Json& r, TubeRadius radius) const {
    radius.mode = *choice(r, "radius_mode", parseRadiusMode, radius.mode, "factor or mm");
    radius.value = number(r, "radius", 1e-6, 1e4, radius.value);
    radius.marginMm = number(r, "margin_mm", 0, 1e3, radius.marginMm);
    return radius;
  }

  static bool namesOwnTf(const TransferFunction& tf, const std::string& preset) {
    return !tf.points.empty() || !preset.empty();
  }

  // The VesselGlyph section (where = "vessel_glyph.").
  VesselGlyphState vesselGlyph(const Json& v) const {
    VesselGlyphState vg;
    vg.centerlines = text(v, "centerlines");
    vg.centerlinesAbsolute = text(v, "centerlines_absolute");
    vg.enabled = flag(v, "enabled", vg.enabled);
    vg.overlay = flag(v, "overlay", vg.overlay);
    VesselGlyphSettings& s = vg.settings;
    s.focus = in("focus").radius(section(v, "focus"), s.focus);
    const SessionReader contextReader = in("context");
    const Json& c = section(v, "context");
    s.context = *contextReader.choice(c, "shape", parseContextShape, s.context, "none, slab or tube");
    s.slab.frontMm = contextReader.number(c, "front_mm", 0, 1e4, s.slab.frontMm);
    s.slab.backMm = contextReader.number(c, "back_mm", 0, 1e4, s.slab.backMm);
    if (c.contains("half_width_mm") && c["half_width_mm"] == "inf")
      s.slab.halfWidthMm = std::numeric_limits<double>::infinity();
    else if (c.contains("half_width_mm") && !c["half_width_mm"].is_number())
      fail(contextReader.where + "half_width_mm is not a number or \"inf\"");
    else s.slab.halfWidthMm = contextReader.number(c, "half_width_mm", 0, 1e5, s.slab.halfWidthMm);
    s.contextTube = contextReader.in("tube").radius(contextReader.section(c, "tube"), s.contextTube);
    s.cleft = flag(v, "cleft", s.cleft);
    s.halfVessel = flag(v, "half_vessel", s.halfVessel);
    s.unknownVesselRadiusMm = number(v, "unknown_vessel_radius_mm", 0, 1e3, s.unknownVesselRadiusMm);
    s.simplifyToleranceMm = number(v, "simplify_tolerance_mm", 0, 100, s.simplifyToleranceMm);
    if (const auto problem = settingsProblem(s)) fail("vessel_glyph: " + *problem);
    if (v.contains("outside")) {
      const std::string outside = text(v, "outside");
      if (outside != "clip" && outside != "main-tf") fail(where + "outside is not clip or main-tf");
      vg.outsideRendered = outside == "main-tf";
    }
    vg.focusTf = tf(v, "focus_tf", vg.focusTf);
    vg.contextTf = tf(v, "context_tf", vg.contextTf);
    if (v.contains("focus_preset")) vg.focusPreset = text(v, "focus_preset");
    if (v.contains("context_preset")) vg.contextPreset = text(v, "context_preset");
    // A session written before the regions followed the main TF names their own TFs.
    vg.focusFollowsMain = flag(v, "focus_follows_main_tf", !namesOwnTf(vg.focusTf, vg.focusPreset));
    vg.contextFollowsMain =
        flag(v, "context_follows_main_tf", !namesOwnTf(vg.contextTf, vg.contextPreset));
    if (!vg.focusFollowsMain && !namesOwnTf(vg.focusTf, vg.focusPreset))
      fail(where + "focus_tf is null and focus_preset empty");
    if (!vg.contextFollowsMain && !namesOwnTf(vg.contextTf, vg.contextPreset))
      fail(where + "context_tf is null and context_preset empty");
    return vg;
  }

  ViewState view(const Json& v) const {
    ViewState view;
    if (v.contains("axis")) {
      const auto axis = parseAxis(text(v, "axis"));
      if (!axis) fail("view axis is not i, j or k");
      view.axis = *axis;
    }
    view.angleDeg = number(v, "angle_deg", -1e6, 1e6, view.angleDeg);
    view.zoom = number(v, "zoom", 1e-3, 1e3, view.zoom);
    view.panPx = pan(v, "view", view.panPx);
    view.degreesPerPixel = number(v, "degrees_per_pixel", 1e-3, 100, view.degreesPerPixel);
    view.autoSpin = flag(v, "auto_spin", view.autoSpin);
    view.spinDegreesPerSecond =
        number(v, "spin_degrees_per_second", -3600, 3600, view.spinDegreesPerSecond);
    return view;
  }

  // A level's adaptive integration: null (off) or its tolerance and steps.
  std::optional<AdaptiveIntegration> adaptive(const Json& a) const {
    if (a.is_null()) return std::nullopt;
    if (!a.is_object()) fail("levels adaptive is not an object or null");
    AdaptiveIntegration settings;
    settings.tolerance = number(a, "tolerance", 1e-6, 1, settings.tolerance);
    settings.initialStep = number(a, "initial_step", 1e-3, 64, settings.initialStep);
    settings.minStep = number(a, "min_step", 1e-3, settings.initialStep, settings.minStep);
    return settings;
  }

  // A level's adaptive sampling: null (off) or its levels and oracle tolerance.
  std::optional<AdaptiveSampling> adaptiveSampling(const Json& a) const {
    if (a.is_null()) return std::nullopt;
    if (!a.is_object()) fail("levels adaptive_sampling is not an object or null");
    AdaptiveSampling settings;
    settings.levels = int(number(a, "levels", 0, kMaxAdaptiveLevels, settings.levels));
    settings.rayLevels = int(number(a, "ray_levels", settings.levels, kMaxAdaptiveLevels,
                                    std::max(settings.levels, settings.rayLevels)));
    settings.tolerance = number(a, "tolerance", 0, 1e6, settings.tolerance);
    return settings;
  }

  Sampling sampling(const Json& s, Sampling sampling) const {
    sampling.isd = number(s, "isd", 1e-3, 100, sampling.isd);
    sampling.osd = number(s, "osd", 1e-3, 100, sampling.osd);
    sampling.ert = number(s, "ert", 0, 1, sampling.ert);
    sampling.preintegrated = flag(s, "preintegrated", sampling.preintegrated);
    if (s.contains("adaptive")) sampling.adaptive = adaptive(s["adaptive"]);
    if (s.contains("adaptive_sampling"))
      sampling.adaptiveSampling = adaptiveSampling(s["adaptive_sampling"]);
    if (sampling.adaptive && sampling.adaptiveSampling)
      fail("levels adaptive and adaptive_sampling exclude each other");
    if (s.contains("filter")) {
      const auto filter = parseFilter(text(s, "filter"));
      if (!filter) fail("levels filter is not nearest, trilinear or mean");
      sampling.filter = *filter;
    }
    return sampling;
  }

  // An image's pan ("pan_px": [x, y] screen pixels) in the view or the CPR section.
  glm::dvec2 pan(const Json& object, const std::string& section, glm::dvec2 fallback) const {
    if (!object.contains("pan_px")) return fallback;
    const Json& pan = object["pan_px"];
    if (!pan.is_array() || pan.size() != 2 || !pan[0].is_number() || !pan[1].is_number())
      fail(section + " pan_px is not [x, y]");
    const glm::dvec2 value(pan[0].get<double>(), pan[1].get<double>());
    if (!std::isfinite(value.x + value.y)) fail(section + " pan_px is not finite");
    return value;
  }

  glm::dvec3 vector(const Json& object, const char* key, glm::dvec3 fallback) const {
    if (!object.contains(key)) return fallback;
    const Json& v = object[key];
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
      fail(where + key + " is not [x, y, z]");
    const glm::dvec3 value(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
    if (!std::isfinite(value.x + value.y + value.z)) fail(where + key + " is not finite");
    return value;
  }

  // The Crop & clip section (where = "clip."); the crop box's minimum never above its maximum.
  ClipState clip(const Json& c) const {
    constexpr double kFar = 1e6;  // mm: beyond any scanner's field
    ClipState clip;
    clip.cropOn = flag(c, "crop_on", clip.cropOn);
    clip.crop.minMm = vector(c, "crop_min_mm", clip.crop.minMm);
    clip.crop.maxMm = vector(c, "crop_max_mm", clip.crop.maxMm);
    if (glm::any(glm::greaterThan(clip.crop.minMm, clip.crop.maxMm)))
      fail(where + "crop_min_mm exceeds crop_max_mm");
    clip.planeOn = flag(c, "plane_on", clip.planeOn);
    clip.facingViewer = flag(c, "facing_viewer", clip.facingViewer);
    if (c.contains("normal_axis")) {  // sessions from before oblique planes
      clip.normal = glm::dvec3(0.0);
      clip.normal[int(*choice(c, "normal_axis", parseAxis, Axis::i, "i, j or k"))] =
          flag(c, "flip_normal", false) ? -1 : 1;
    }
    clip.normal = vector(c, "normal", clip.normal);
    if (const double length = glm::length(clip.normal); !(length > 1e-9) || !std::isfinite(length))
      fail(where + "normal is not a direction");
    clip.normal = glm::normalize(clip.normal);
    clip.planeOffsetMm = number(c, "plane_offset_mm", -kFar, kFar, clip.planeOffsetMm);
    clip.slabOn = flag(c, "slab_on", clip.slabOn);
    clip.slab.offsetMm = number(c, "slab_offset_mm", -kFar, kFar, clip.slab.offsetMm);
    clip.slab.thicknessMm = number(c, "slab_thickness_mm", 1e-3, kFar, clip.slab.thicknessMm);
    return clip;
  }

  // The slice view (where = "slices."): a window of at least 1 HU.
  SliceViewState slices(const Json& s) const {
    SliceViewState slices;
    slices.shown = flag(s, "shown", slices.shown);
    slices.windowLevel.window = number(s, "window", 1, 1e5, slices.windowLevel.window);
    slices.windowLevel.level = number(s, "level", -1e5, 1e5, slices.windowLevel.level);
    if (s.contains("cursor_mm") && !s["cursor_mm"].is_null())
      slices.cursorMm = vector(s, "cursor_mm", glm::dvec3(0.0));
    const Json& panes = section(s, "panes");
    // Named: section() may return the reader's own empty object, which must outlive `view`.
    const SessionReader panesReader = in("panes");
    for (int o = 0; o < 3; ++o) {
      const char* name = sliceOrientationName(SliceOrientation(o));
      const SessionReader pane = panesReader.in(name);
      const Json& view = panesReader.section(panes, name);
      SlicePaneView& set = slices.panes[o];
      set.zoom = pane.number(view, "zoom", kMinSliceZoom, kMaxSliceZoom, set.zoom);
      set.panPx = pane.pan(view, pane.where.substr(0, pane.where.size() - 1), set.panPx);
    }
    return slices;
  }

  CprState cpr(const Json& c) const {
    CprState cpr;
    cpr.shown = flag(c, "shown", cpr.shown);
    if (c.contains("mode")) {
      const auto mode = parseCprMode(text(c, "mode"));
      if (!mode) fail("cpr mode is not projected, stretched or straightened");
      cpr.mode = *mode;
    }
    if (c.contains("path") && !c["path"].is_number_integer())
      fail("cpr path is not a path index or -1 (all)");
    cpr.path = int(number(c, "path", -1, 1e6, cpr.path));
    if (c.contains("colouring")) {
      const std::string coloring = text(c, "colouring");
      const CprColoring all[] = {CprColoring::ctaLumen, CprColoring::calcium, CprColoring::focusTf};
      const auto known = std::find_if(std::begin(all), std::end(all),
                                      [&](CprColoring c) { return coloring == cprColoringName(c); });
      if (known == std::end(all)) fail("cpr colouring is not cta-lumen, calcium or focus-tf");
      cpr.coloring = *known;
      if (cpr.coloring == CprColoring::calcium) cpr.window = kCalciumWindow;  // its preset
    }
    cpr.window.window = number(c, "window", 1, 1e5, cpr.window.window);
    cpr.window.level = number(c, "level", -1e5, 1e5, cpr.window.level);
    cpr.widthMm = number(c, "width_mm", kMinCprWidthMm, kMaxCprWidthMm, cpr.widthMm);
    cpr.zoom = number(c, "zoom", kMinCprZoom, kMaxCprZoom, cpr.zoom);
    cpr.panPx = pan(c, "cpr", cpr.panPx);
    cpr.hybrid = flag(c, "hybrid", cpr.hybrid);
    cpr.transitionMm = number(c, "transition_mm", 0, kMaxTransitionMm, cpr.transitionMm);
    if (c.contains("cursor") && !c["cursor"].is_null())
      cpr.cursor = in("cpr").in("cursor").cprCursor(c["cursor"]);
    return cpr;
  }

  CprCursor cprCursor(const Json& c) const {
    // `where` is "cpr.cursor." here.
    if (!c.is_object()) fail("cpr cursor is not an object with path and arc_mm");
    if (!c.contains("path") || !c["path"].is_number_integer()) fail(where + "path is not a path index");
    return CprCursor{int(number(c, "path", 0, 1e6, 0)), number(c, "arc_mm", 0, 1e7, 0)};
  }

  // The TF a session names by its preset (or TF file); none named: the first preset, as at start.
  TransferFunction presetTf(std::string& preset) const {
    if (preset.empty()) {
      const std::vector<Preset> presets = listPresets();
      if (presets.empty()) return {};
      preset = presets.front().id;
    }
    try {
      return loadPresetOrFile(preset);
    } catch (const InputError&) {
      fail("tf_preset '" + preset + "' is neither a TF preset nor a TF file");
    }
  }

  Document session(const Json& json) const {
    if (!json.is_object()) fail("a session is a JSON object");
    if (json.contains("format") && text(json, "format") != kFormat) fail("is not an angioray session");
    Document session;
    session.dataset = text(json, "dataset");
    session.view = view(section(json, "view"));
    session.tfPreset = text(json, "tf_preset");
    if (json.contains("transfer_function")) {
      if (!json["transfer_function"].is_object()) fail("transfer_function is not an object");
      session.tf = parseTransferFunction(json["transfer_function"].dump(), source);
    } else {
      session.tf = presetTf(session.tfPreset);  // a hand-written session may name its TF only
    }
    const std::string mode = json.contains("mode") ? text(json, "mode") : "dvr";
    if (mode != "dvr" && mode != "mip") fail("mode is not dvr or mip");
    session.mode = mode == "mip" ? Compositing::mip : Compositing::dvr;
    const Json& shading = section(json, "shading");
    session.shading.enabled = flag(shading, "enabled", session.shading.enabled);
    session.shading.ka = number(shading, "ka", 0, 10, session.shading.ka);
    session.shading.kd = number(shading, "kd", 0, 10, session.shading.kd);
    const Json& levels = section(json, "levels");
    for (int q = 0; q < kQualityLevels; ++q)
      session.levels[q] = sampling(section(levels, toString(Quality(q))), session.levels[q]);
    session.cpr = cpr(section(json, "cpr"));
    session.clip = in("clip").clip(section(json, "clip"));
    session.slices = in("slices").slices(section(json, "slices"));
    session.vesselGlyph = in("vessel_glyph").vesselGlyph(section(json, "vessel_glyph"));
    const Json& labels = section(json, "labels");
    session.labels.file = in("labels").text(labels, "file");
    session.labels.showRemoved = in("labels").flag(labels, "show_removed", false);
    if (json.contains("vessels")) session.vessels = parseVessels(json["vessels"], source);
    for (const auto& [name, open] : section(json, "panels").items()) {
      if (!open.is_boolean()) fail("panels " + name + " is not true or false");
      session.panelsOpen[name] = open.get<bool>();
    }
    if (json.contains("recent_files")) {
      const Json& recent = json["recent_files"];
      if (!recent.is_array()) fail("recent_files is not a list");
      for (const Json& file : recent) {
        if (!file.is_string()) fail("recent_files holds something that is not a string");
        if (session.recentFiles.size() < kMaxRecentFiles)
          session.recentFiles.push_back(file.get<std::string>());
      }
    }
    return session;
  }
};

}  // namespace

std::string toJson(const Document& session) {
  const ViewState& v = session.view;
  Json levels = Json::object();
  for (int q = 0; q < kQualityLevels; ++q)
    levels[toString(Quality(q))] = Json::parse(samplingJson(session.levels[q]).dump());
  Json panels = Json::object();
  for (const auto& [name, open] : session.panelsOpen) panels[name] = open;
  const Json json = {
      {"format", kFormat},
      {"version", kVersion},
      {"dataset", session.dataset},
      {"view",
       {{"axis", toString(v.axis)},
        {"angle_deg", v.angleDeg},
        {"zoom", v.zoom},
        {"pan_px", {v.panPx.x, v.panPx.y}},
        {"degrees_per_pixel", v.degreesPerPixel},
        {"auto_spin", v.autoSpin},
        {"spin_degrees_per_second", v.spinDegreesPerSecond}}},
      {"transfer_function", Json::parse(toJson(session.tf))},
      {"tf_preset", session.tfPreset},
      {"mode", session.mode == Compositing::mip ? "mip" : "dvr"},
      {"shading",
       {{"enabled", session.shading.enabled}, {"ka", session.shading.ka}, {"kd", session.shading.kd}}},
      {"levels", levels},
      {"cpr", cprJson(session.cpr)},
      {"clip", clipJson(session.clip)},
      {"slices", slicesJson(session.slices)},
      {"vessel_glyph", vesselGlyphJson(session.vesselGlyph)},
      {"labels", {{"file", session.labels.file}, {"show_removed", session.labels.showRemoved}}},
      {"vessels", vesselsJson(session.vessels)},
      {"panels", panels},
      {"recent_files", session.recentFiles},
  };
  return json.dump(2);
}

Document parseSession(const std::string& text, const fs::path& source) {
  return SessionReader{source}.session(parseJsonText(text, source));
}

Document loadSession(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, fs::exists(path) ? "cannot be read" : "does not exist");
  std::stringstream text;
  text << in.rdbuf();
  return parseSession(text.str(), path);
}

void saveSession(const Document& session, const fs::path& path) {
  std::error_code error;
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), error);
  if (error) throw InputError(path, "cannot create its folder: " + error.message());
  writeAtomically(path, [&](const fs::path& temp) {
    std::ofstream out(temp);
    out << toJson(session) << '\n';
    if (!out) throw InputError(path, "cannot be written");
  });
}

fs::path configDirectory() {
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  if (xdg && *xdg) return fs::path(xdg) / "angioray";
  const char* home = std::getenv("HOME");
  return fs::path(home && *home ? home : ".") / ".config" / "angioray";
}

fs::path lastSessionPath() { return configDirectory() / "last-session.json"; }

}  // namespace angio
