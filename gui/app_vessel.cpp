// The VesselGlyph panel of App (issue 5 item 7; thesis ch. 5): load centerlines, show them over the
// image, pick the focus / context shapes and TFs; every change makes a new RegionSource, which the
// progressive renderer takes as a new request (fast, medium, high as for any other change).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "core/view_geometry.h"
#include "gui/app.h"
#include "io/centerline_file.h"
#include "vessel/vessel_glyph_spec.h"

namespace angio {

namespace {

constexpr const char* kTargetNames[] = {"main", "focus", "context"};
constexpr const char* kContextNames[] = {"none", "slab", "tube"};

bool sameTube(const TubeRadius& a, const TubeRadius& b) {
  return a.mode == b.mode && a.value == b.value && a.marginMm == b.marginMm;
}

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

// What the hybrid's finish step depends on beyond the regions and the focus TF ("" = off).
std::string hybridSettingsKey(const SessionCpr& cpr) {
  if (!cpr.hybrid) return "";
  char key[96];
  std::snprintf(key, sizeof key, "%d %d %.17g", cpr.path, int(cpr.colouring), cpr.transitionMm);
  return key;
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

bool sameGlyphSettings(const VesselGlyphSettings& a, const VesselGlyphSettings& b) {
  return sameTube(a.focus, b.focus) && a.context == b.context && a.slab.frontMm == b.slab.frontMm &&
         a.slab.backMm == b.slab.backMm && a.slab.halfWidthMm == b.slab.halfWidthMm &&
         sameTube(a.contextTube, b.contextTube) && a.cleft == b.cleft &&
         a.halfVessel == b.halfVessel && a.unknownVesselRadiusMm == b.unknownVesselRadiusMm &&
         a.simplifyToleranceMm == b.simplifyToleranceMm;
}

void App::loadVesselCenterlines(const std::string& path) {
  VesselGlyphPanel& vg = vessel_;
  try {
    std::string warnings;
    CenterlineLoadOptions options;
    options.warn = [&](const std::string& warning) { warnings += warning + "\n"; };
    Centerlines loaded = loadCenterlines(path, options);
    checkCenterlinesInside(loaded, data_.volume, options);
    char summary[160];
    std::snprintf(summary, sizeof summary, "loaded %zu centerline paths (%zu points) from ",
                  loaded.paths.size(), pointCount(loaded));
    vg.physical = std::move(loaded);
    vg.file = path;
    vg.warnings = warnings;
    vg.error.clear();
    vg.inVolume.reset();
    vg.builder.reset();
    message_ = summary + path;
  } catch (const std::exception& error) {
    vg.error = error.what();
    message_ = error.what();
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
    vg.builder.reset();
  }
  return &*vg.inVolume;
}

TransferFunction& App::editedTf() {
  switch (vessel_.editing) {
    case TfTarget::focus: return vessel_.focusTf;
    case TfTarget::context: return vessel_.contextTf;
    case TfTarget::main: break;
  }
  return state_.tf;
}

std::string& App::editedPreset() {
  switch (vessel_.editing) {
    case TfTarget::focus: return vessel_.focusPreset;
    case TfTarget::context: return vessel_.contextPreset;
    case TfTarget::main: break;
  }
  return state_.tfPreset;
}

void App::ensureVesselTfs() {
  VesselGlyphPanel& vg = vessel_;
  try {
    if (vg.focusTf.points.empty()) vg.focusTf = loadPresetOrFile(vg.focusPreset);
    if (vg.contextTf.points.empty()) vg.contextTf = loadPresetOrFile(vg.contextPreset);
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
  ensureVesselTfs();
  ImGui::SetNextItemWidth(230);
  ImGui::InputText("##vgpath", &vg.path);
  noteRect("vg_path");
  ImGui::SameLine();
  if (ImGui::Button("Load centerlines...")) loadVesselCenterlines(vg.path);
  noteRect("vg_load");
  if (!vg.error.empty()) ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", vg.error.c_str());
  if (vg.physical)
    ImGui::TextDisabled("%zu paths, %zu points: %s", vg.physical->paths.size(),
                        pointCount(*vg.physical), vg.file.c_str());
  if (!vg.warnings.empty()) ImGui::TextColored(ImVec4(1, 0.8f, 0.4f, 1), "%s", vg.warnings.c_str());
  if (!vg.physical) return;  // the rest once there are centerlines

  ImGui::Checkbox("VesselGlyph on", &vg.enabled);
  noteRect("vg_enable");
  ImGui::SameLine();
  ImGui::Checkbox("centerline overlay", &vg.overlay);
  noteRect("vg_overlay");
  if (!vg.problem.empty()) ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", vg.problem.c_str());

  VesselGlyphSettings& s = vg.settings;
  ImGui::TextUnformatted("focus radius");
  ImGui::SameLine();
  if (ImGui::RadioButton("x vessel radius", s.focus.mode == RadiusMode::kVesselFactor))
    s.focus = {RadiusMode::kVesselFactor, 2.0, 0.0};
  ImGui::SameLine();
  if (ImGui::RadioButton("mm##focus", s.focus.mode == RadiusMode::kConstant))
    s.focus = {RadiusMode::kConstant, 5.0, 0.0};
  if (s.focus.mode == RadiusMode::kVesselFactor) {
    ImGui::SetNextItemWidth(180);
    const double lo = 0.5, hi = 6;
    ImGui::SliderScalar("x radius##focus", ImGuiDataType_Double, &s.focus.value, &lo, &hi, "%.2fx");
  } else {
    sliderMm("radius##focus", s.focus.value, 0.5, 40);
  }

  ImGui::TextUnformatted("context");
  for (int n = 0; n < 3; ++n) {
    ImGui::SameLine();
    char label[32];
    std::snprintf(label, sizeof label, "%s##context", kContextNames[n]);
    if (ImGui::RadioButton(label, int(s.context) == n)) s.context = ContextShape(n);
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
  if (ImGui::RadioButton("clipped", !vg.outsideRendered)) vg.outsideRendered = false;
  ImGui::SameLine();
  if (ImGui::RadioButton("main TF", vg.outsideRendered)) vg.outsideRendered = true;
  noteRect("vg_outside_main");
  ImGui::Checkbox("foreground cleft", &s.cleft);
  noteRect("vg_cleft");
  ImGui::SameLine();
  ImGui::Checkbox("half vessel", &s.halfVessel);
  noteRect("vg_half_vessel");
  regionTfCombo("focus TF", presets_, vg.focusTf, vg.focusPreset, message_);
  regionTfCombo("context TF", presets_, vg.contextTf, vg.contextPreset, message_);
  ImGui::TextDisabled("edit them in the TF editor: \"TF editor edits\" above it");
}

// The request's regions: null for plain DVR (VesselGlyph off, nothing loaded, or a problem);
// a new source whenever the shape, a region TF or the outside TF changed, else the last one.
std::shared_ptr<const RegionSource> App::vesselRegions() {
  VesselGlyphPanel& vg = vessel_;
  vg.problem.clear();
  if (!vg.enabled || !vg.physical) return vg.source = nullptr;
  ensureVesselTfs();
  bool changed = !vg.source;
  try {
    const Centerlines* centerlines = framedCenterlines();
    if (!vg.builder || !sameGlyphSettings(vg.builder->builder.settings(), vg.settings)) {
      vg.builder = std::make_shared<GuardedRegionBuilder>(*centerlines, vg.settings);
      changed = true;
    }
  } catch (const std::exception& error) {
    vg.problem = error.what();
    return vg.source = nullptr;
  }
  const auto refresh = [&](std::shared_ptr<const TfTable>& table, TransferFunction& builtFrom,
                           const TransferFunction& tf) {
    if (table && sameTf(builtFrom, tf)) return;
    table = std::make_shared<const TfTable>(buildTable(tf));
    builtFrom = tf;
    changed = true;
  };
  refresh(vg.focusTable, vg.focusTableTf, vg.focusTf);
  refresh(vg.contextTable, vg.contextTableTf, vg.contextTf);
  const std::shared_ptr<const TfTable> outside = vg.outsideRendered ? table_ : nullptr;
  if (outside != vg.outsideTable) vg.outsideTable = outside, changed = true;
  const std::string hybrid = hybridSettingsKey(state_.cpr);
  if (hybrid != vg.hybridFor) vg.hybridFor = hybrid, changed = true;
  if (!changed) return vg.source;

  auto source = std::make_shared<RegionSource>();
  source->build = [builder = vg.builder](const ViewGeometry& view, RayRegions& out) {
    std::lock_guard lock(builder->mutex);
    builder->builder.build(view, out);
  };
  source->focus = vg.focusTable;
  source->context = vg.contextTable;
  source->outside = vg.outsideTable;
  source->finish = hybridFinishStep();  // the DVR+CPR hybrid, if on (gui/app_hybrid.cpp)
  return vg.source = std::move(source);
}

// The centerlines projected with the shown frame's view, over the image (follows zoom and pan).
void App::drawCenterlineOverlay() {
  if (!vessel_.overlay || !vessel_.physical || !shown_ || !viewport_.hasImage) return;
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
  return {{"enabled", vg.enabled},
          {"rendering", vg.source != nullptr},
          {"overlay", vg.overlay},
          {"centerlines", vg.file},
          {"paths", vg.physical ? vg.physical->paths.size() : 0},
          {"focus", focusSpecText(vg.settings.focus)},
          {"context", contextSpecText(vg.settings)},
          {"outside", vg.outsideRendered ? "main-tf" : "clip"},
          {"cleft", vg.settings.cleft},
          {"half_vessel", vg.settings.halfVessel},
          {"focus_tf", vg.focusPreset.empty() ? vg.focusTf.name : vg.focusPreset},
          {"context_tf", vg.contextPreset.empty() ? vg.contextTf.name : vg.contextPreset},
          {"tf_editing", kTargetNames[int(vg.editing)]},
          {"error", vg.error},
          {"problem", vg.problem},
          {"cpr", cprReport()},
          {"hybrid", hybridReport()}};
}

}  // namespace angio
