// The VesselGlyph panel of App (issue 5 item 7; thesis ch. 5): load centerlines, show them over the
// image, pick the focus / context shapes and TFs; every change makes a new RegionSource, which the
// progressive renderer takes as a new request (fast, medium, high as for any other change).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "core/view_geometry.h"
#include "gui/app.h"
#include "io/centerline_file.h"
#include "vessel/vessel_glyph_spec.h"

namespace angio {

namespace fs = std::filesystem;

namespace {

constexpr const char* kTargetNames[] = {"main", "focus", "context"};
constexpr const char* kContextNames[] = {"none", "slab", "tube"};

// A slider for a double; true when it changed.
bool sliderMm(const char* label, double& value, double lo, double hi, const char* format = "%.1f mm") {
  ImGui::SetNextItemWidth(180);
  return ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &lo, &hi, format);
}

// The preset combo of a region TF: loads the chosen preset into `tf`.
void regionTfCombo(const char* label, const std::vector<Preset>& presets, TransferFunction& tf,
                   std::string& preset, std::string& message) {
  const std::string current = preset.empty() ? tf.name + " (edited)" : preset;
  ImGui::SetNextItemWidth(200);
  if (!ImGui::BeginCombo(label, current.c_str())) return;
  for (const Preset& candidate : presets) {
    if (!ImGui::Selectable(candidate.id.c_str(), candidate.id == preset)) continue;
    try {
      tf = loadPresetOrFile(candidate.file.string());
      preset = candidate.id;
    } catch (const std::exception& error) {
      message = error.what();
    }
  }
  ImGui::EndCombo();
}

std::size_t pointCount(const Centerlines& centerlines) {
  std::size_t n = 0;
  for (const CenterlinePath& path : centerlines.paths) n += path.points.size();
  return n;
}

}  // namespace

glm::dvec2 imagePixelOf(const ViewGeometry& view, const glm::dvec3& pointMm) {
  const glm::dvec3 offset = pointMm - view.centre;
  return {glm::dot(offset, view.right) / view.pixelMm + view.width * 0.5,
          view.height * 0.5 - glm::dot(offset, view.up) / view.pixelMm};
}

ImVec2 App::dvrScreenOf(const ViewGeometry& shownView, const glm::dvec3& pointMm) const {
  const glm::dvec2 pixel = imagePixelOf(shownView, pointMm);
  const ImVec2 origin = viewport_.imageMin;
  return {origin.x + float(pixel.x / std::max(shownView.width, 1)) * (viewport_.imageMax.x - origin.x),
          origin.y + float(pixel.y / std::max(shownView.height, 1)) * (viewport_.imageMax.y - origin.y)};
}

// Reads the file off the UI thread; pollCenterlineLoad takes the result.
void App::loadVesselCenterlines(const CenterlineLoad& request) {
  VesselGlyphPanel& vg = vessel_;
  vg.loading = request;
  vg.error.clear();
  message_ = "loading centerlines " + request.given;
  vg.load.start([request](JobControl&) {
    // A session's absolute path first (it works from any folder), else the file as given; when
    // neither exists, the error names the absolute one.
    std::error_code error;
    const bool absoluteThere = !request.absolute.empty() && fs::exists(request.absolute, error);
    LoadedCenterlines loaded;
    loaded.file = absoluteThere || (!request.absolute.empty() && !fs::exists(request.given, error))
                      ? request.absolute
                      : request.given;
    CenterlineLoadOptions options;
    options.warn = [&loaded](const std::string& warning) { loaded.warnings += warning + "\n"; };
    loaded.physical = loadCenterlines(loaded.file, options);
    return loaded;
  });
}

// The session's centerline file (state_.vesselGlyph), loaded in the background; no file: none.
void App::loadSessionCenterlines() {
  const SessionVesselGlyph& set = state_.vesselGlyph;
  vessel_.load.stop();
  dropCenterlines();
  if (set.centerlines.empty() && set.centerlinesAbsolute.empty()) return;
  vessel_.path = set.centerlines.empty() ? set.centerlinesAbsolute : set.centerlines;
  loadVesselCenterlines({vessel_.path, set.centerlinesAbsolute, CenterlineLoad::From::session});
}

void App::dropCenterlines() {
  VesselGlyphPanel& vg = vessel_;
  vg.physical.reset();
  vg.file.clear();
  vg.warnings.clear();
  vg.error.clear();
  vg.inVolume.reset();
  vg.framedFor.clear();
}

// Once loaded and no dataset load is running (the points are checked against the shown dataset).
void App::pollCenterlineLoad() {
  VesselGlyphPanel& vg = vessel_;
  if (!vg.load.ready() || load_.running()) return;
  SessionVesselGlyph& set = state_.vesselGlyph;
  try {
    LoadedCenterlines loaded = vg.load.take();
    CenterlineLoadOptions options;
    options.warn = [&loaded](const std::string& warning) { loaded.warnings += warning + "\n"; };
    checkCenterlinesInside(loaded.physical, data_.volume, options);
    char summary[160];
    std::snprintf(summary, sizeof summary, "loaded %zu centerline paths (%zu points) from ",
                  loaded.physical.paths.size(), pointCount(loaded.physical));
    message_ = summary + loaded.file;
    vg.physical = std::move(loaded.physical);
    vg.file = loaded.file;
    vg.warnings = std::move(loaded.warnings);
    vg.error.clear();
    vg.inVolume.reset();
      set.centerlines = vg.loading.given;
    std::error_code error;
    const fs::path absolute = fs::absolute(vg.file, error);
    set.centerlinesAbsolute = error ? vg.file : absolute.lexically_normal().string();
  } catch (const std::exception& error) {
    vg.error = error.what();
    message_ = error.what();
    // A session's file that is gone or broken: the rest of the session stands, VesselGlyph is off.
    if (vg.loading.from == CenterlineLoad::From::session) set.enabled = false;
  }
}

// The centerlines in the shown dataset's volume frame (mapped again after a dataset change).
const Centerlines* App::framedCenterlines() {
  VesselGlyphPanel& vg = vessel_;
  if (!vg.physical) return nullptr;
  const glm::ivec3 dims = data_.volume.dims;
  const std::string key = data_.name + " " + std::to_string(dims.x) + "x" + std::to_string(dims.y) +
                          "x" + std::to_string(dims.z);
  if (!vg.inVolume || vg.framedFor != key) {
    vg.inVolume = toVolumeFrame(*vg.physical, data_.volume);
    vg.framedFor = key;
    }
  return &*vg.inVolume;
}

TransferFunction& App::editedTf() {
  switch (vessel_.editing) {
    case TfTarget::focus: return state_.vesselGlyph.focusTf;
    case TfTarget::context: return state_.vesselGlyph.contextTf;
    case TfTarget::main: break;
  }
  return state_.tf;
}

std::string& App::editedPreset() {
  switch (vessel_.editing) {
    case TfTarget::focus: return state_.vesselGlyph.focusPreset;
    case TfTarget::context: return state_.vesselGlyph.contextPreset;
    case TfTarget::main: break;
  }
  return state_.tfPreset;
}

void App::ensureVesselTfs() {
  SessionVesselGlyph& set = state_.vesselGlyph;
  try {
    if (set.focusTf.points.empty()) set.focusTf = loadPresetOrFile(set.focusPreset);
    if (set.contextTf.points.empty()) set.contextTf = loadPresetOrFile(set.contextPreset);
  } catch (const std::exception& error) {
    message_ = error.what();
  }
}

// "TF editor edits: main | focus | context": each target keeps its own undo stack.
void App::drawTfTargetSelector() {
  if (!vessel_.physical && vessel_.editing == TfTarget::main) return;
  ImGui::TextUnformatted("TF editor edits:");
  for (int n = 0; n < 3; ++n) {
    ImGui::SameLine();
    const TfTarget target = TfTarget(n);
    char label[32];
    std::snprintf(label, sizeof label, "%s##tftarget", kTargetNames[n]);
    if (ImGui::RadioButton(label, vessel_.editing == target) && vessel_.editing != target &&
        !tfView_.gestureBefore) {
      ensureVesselTfs();
      vessel_.histories[int(vessel_.editing)] = tfHistory_;
      tfHistory_ = vessel_.histories[n];
      vessel_.editing = target;
      tfView_.selected = tfView_.dragging = -1;
    }
    noteRect(std::string("vg_edit_") + kTargetNames[n]);
  }
}

void App::drawVesselSection() {
  if (!sectionHeader("VesselGlyph")) return;
  VesselGlyphPanel& vg = vessel_;
  SessionVesselGlyph& set = state_.vesselGlyph;
  ensureVesselTfs();
  ImGui::SetNextItemWidth(230);
  ImGui::InputText("##vgpath", &vg.path);
  noteRect("vg_path");
  ImGui::SameLine();
  ImGui::BeginDisabled(vg.load.running());
  if (ImGui::Button("Load centerlines...")) loadVesselCenterlines({vg.path, "", CenterlineLoad::From::panel});
  ImGui::EndDisabled();
  noteRect("vg_load");
  if (vg.load.running()) ImGui::TextDisabled("loading %s ...", vg.loading.given.c_str());
  if (!vg.error.empty()) ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", vg.error.c_str());
  if (vg.physical)
    ImGui::TextDisabled("%zu paths, %zu points: %s", vg.physical->paths.size(),
                        pointCount(*vg.physical), vg.file.c_str());
  if (!vg.warnings.empty()) ImGui::TextColored(ImVec4(1, 0.8f, 0.4f, 1), "%s", vg.warnings.c_str());
  if (!vg.physical) return;  // the rest once there are centerlines

  ImGui::Checkbox("VesselGlyph on", &set.enabled);
  noteRect("vg_enable");
  ImGui::SameLine();
  ImGui::Checkbox("centerline overlay", &set.overlay);
  noteRect("vg_overlay");
  if (!vg.problem.empty()) ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", vg.problem.c_str());

  VesselGlyphSettings& s = set.settings;
  ImGui::TextUnformatted("focus radius");
  ImGui::SameLine();
  if (ImGui::RadioButton("x vessel radius", s.focus.mode == RadiusMode::kVesselFactor))
    s.focus = {RadiusMode::kVesselFactor, 2.0, 0.0};
  noteRect("vg_focus_factor");
  ImGui::SameLine();
  if (ImGui::RadioButton("mm##focus", s.focus.mode == RadiusMode::kConstant))
    s.focus = {RadiusMode::kConstant, 5.0, 0.0};
  noteRect("vg_focus_mm");
  if (s.focus.mode == RadiusMode::kVesselFactor) {
    ImGui::SetNextItemWidth(180);
    const double lo = 0.5, hi = 6;
    ImGui::SliderScalar("x radius##focus", ImGuiDataType_Double, &s.focus.value, &lo, &hi, "%.2fx");
  } else {
    sliderMm("radius##focus", s.focus.value, 0.5, 40);
  }
  noteRect("vg_focus_radius");

  ImGui::TextUnformatted("context");
  for (int n = 0; n < 3; ++n) {
    ImGui::SameLine();
    char label[32];
    std::snprintf(label, sizeof label, "%s##context", kContextNames[n]);
    if (ImGui::RadioButton(label, int(s.context) == n)) s.context = ContextShape(n);
    noteRect(std::string("vg_context_") + kContextNames[n]);
  }
  if (s.context == ContextShape::kSlab) {
    sliderMm("in front (d1)", s.slab.frontMm, 0, 200);
    sliderMm("behind (d2)", s.slab.backMm, 0, 200);
    sliderMm("half width", s.slab.halfWidthMm, 5, 300);
  } else if (s.context == ContextShape::kTube) {
    s.contextTube.mode = RadiusMode::kConstant;
    sliderMm("radius##context", s.contextTube.value, 1, 150);
  }
  ImGui::TextUnformatted("outside");
  ImGui::SameLine();
  if (ImGui::RadioButton("clipped", !set.outsideRendered)) set.outsideRendered = false;
  ImGui::SameLine();
  if (ImGui::RadioButton("main TF", set.outsideRendered)) set.outsideRendered = true;
  noteRect("vg_outside_main");
  ImGui::Checkbox("foreground cleft", &s.cleft);
  noteRect("vg_cleft");
  ImGui::SameLine();
  ImGui::Checkbox("half vessel", &s.halfVessel);
  noteRect("vg_half_vessel");
  regionTfCombo("focus TF", presets_, set.focusTf, set.focusPreset, message_);
  regionTfCombo("context TF", presets_, set.contextTf, set.contextPreset, message_);
  ImGui::TextDisabled("edit them in the TF editor: \"TF editor edits\" above it");
}

// The centerlines projected with the shown frame's view, over the image (follows zoom and pan).
void App::drawCenterlineOverlay() {
  if (!state_.vesselGlyph.overlay || !vessel_.physical || !shown_ || !viewport_.hasImage) return;
  const Centerlines* centerlines = nullptr;
  try {
    centerlines = framedCenterlines();
  } catch (const std::exception& error) {
    vessel_.problem = error.what();
    return;
  }
  const ViewGeometry view = makeViewGeometry(data_.volume, shown_->params);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(viewport_.min, viewport_.max, true);
  std::vector<ImVec2> screen;
  for (const CenterlinePath& path : centerlines->paths) {
    screen.clear();
    for (const CenterlinePoint& point : path.points) screen.push_back(dvrScreenOf(view, point.positionMm));
    if (screen.size() >= 2)
      draw->AddPolyline(screen.data(), int(screen.size()), IM_COL32(40, 230, 255, 200), ImDrawFlags_None, 1.5f);
  }
  draw->PopClipRect();
}

nlohmann::json App::vesselReport() const {
  const VesselGlyphPanel& vg = vessel_;
  const SessionVesselGlyph& set = state_.vesselGlyph;
  return {{"enabled", set.enabled},
          {"rendering", scene_ && scene_->hasRegions()},
          {"overlay", set.overlay},
          {"centerlines", vg.file},
          {"paths", vg.physical ? vg.physical->paths.size() : 0},
          {"focus", focusSpecText(set.settings.focus)},
          {"context", contextSpecText(set.settings)},
          {"outside", set.outsideRendered ? "main-tf" : "clip"},
          {"cleft", set.settings.cleft},
          {"half_vessel", set.settings.halfVessel},
          {"focus_tf", set.focusPreset.empty() ? set.focusTf.name : set.focusPreset},
          {"context_tf", set.contextPreset.empty() ? set.contextTf.name : set.contextPreset},
          {"tf_editing", kTargetNames[int(vg.editing)]},
          {"error", vg.error},
          {"problem", vg.problem},
          {"cpr", cprReport()},
          {"hybrid", hybridReport()}};
}

}  // namespace angio
