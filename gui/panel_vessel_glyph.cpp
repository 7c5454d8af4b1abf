#include "gui/panel_vessel_glyph.h"

#include <cstdio>
#include <exception>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "gui/message_row.h"

namespace angio {

namespace {

constexpr const char* kContextNames[] = {"none", "slab", "tube"};

// A slider for a double; true when it changed.
bool sliderMm(const char* label, double& value, double lo, double hi, const char* format = "%.1f mm") {
  ImGui::SetNextItemWidth(180);
  return ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &lo, &hi, format,
                             ImGuiSliderFlags_AlwaysClamp);
}

// The preset combo of a region TF: the main TF it follows first, then the presets; a chosen preset
// is loaded into `tf` and the region stops following.
void regionTfCombo(const char* label, TfTarget region, const std::vector<Preset>& presets,
                   bool& followsMain, TransferFunction& tf, std::string& preset, std::string& message) {
  const std::string current =
      followsMain ? followingTfLabel(region) : (preset.empty() ? tf.name + " (edited)" : preset);
  ImGui::SetNextItemWidth(200);
  if (!ImGui::BeginCombo(label, current.c_str())) return;
  if (ImGui::Selectable(followingTfLabel(region), followsMain)) followsMain = true;
  for (const Preset& candidate : presets) {
    if (!ImGui::Selectable(candidate.id.c_str(), !followsMain && candidate.id == preset)) continue;
    try {
      tf = loadPresetOrFile(candidate.file.string());
      preset = candidate.id;
      followsMain = false;
    } catch (const std::exception& error) {
      message = error.what();
    }
  }
  ImGui::EndCombo();
}

// The file field, "...", the Load button and what the last load gave.
void drawLoading(VesselGlyphPanelUi& ui, const VesselGlyphPanelInfo& info,
                 VesselGlyphPanelResult& result, WidgetRects& rects) {
  ImGui::SetNextItemWidth(200);
  ImGui::InputText("##vgpath", &ui.path);
  noteRect(rects, "vg_path");
  ImGui::BeginDisabled(info.loading);
  result.browseCenterlines = drawBrowseButton("vg", rects);
  ImGui::SameLine();
  result.loadCenterlines = ImGui::Button("Load centerlines");
  ImGui::EndDisabled();
  noteRect(rects, "vg_load");
  // Two rows always: what is loaded (or loading), then an error, why VesselGlyph does not render,
  // or the load's warnings.
  std::string loaded;
  if (info.loading) loaded = "loading " + info.loadingFile + " ...";
  else if (info.physical)
    loaded = std::to_string(info.physical->paths.size()) + " paths, " +
             std::to_string(centerlinePointCount(*info.physical)) + " points: " + info.file;
  drawMessageRow({{MessageKind::note, loaded}});
  drawMessageRow({{MessageKind::error, info.error},
                  {MessageKind::error, info.physical ? info.problem : ""},
                  {MessageKind::warning, info.warnings}});
}

void drawFocus(TubeRadius& focus, WidgetRects& rects) {
  ImGui::TextUnformatted("focus radius");
  ImGui::SameLine();
  if (ImGui::RadioButton("x vessel radius", focus.mode == RadiusMode::vesselFactor))
    focus = {RadiusMode::vesselFactor, 2.0, 0.0};
  noteRect(rects, "vg_focus_factor");
  ImGui::SameLine();
  if (ImGui::RadioButton("mm##focus", focus.mode == RadiusMode::constant))
    focus = {RadiusMode::constant, 5.0, 0.0};
  noteRect(rects, "vg_focus_mm");
  if (focus.mode == RadiusMode::vesselFactor) {
    ImGui::SetNextItemWidth(180);
    const double lo = 0.5, hi = 6;
    ImGui::SliderScalar("x radius##focus", ImGuiDataType_Double, &focus.value, &lo, &hi, "%.2fx",
                        ImGuiSliderFlags_AlwaysClamp);
  } else {
    sliderMm("radius##focus", focus.value, 0.5, 40);
  }
  noteRect(rects, "vg_focus_radius");
}

void drawContext(VesselGlyphSettings& s, WidgetRects& rects) {
  ImGui::TextUnformatted("context");
  for (int n = 0; n < 3; ++n) {
    ImGui::SameLine();
    char label[32];
    std::snprintf(label, sizeof label, "%s##context", kContextNames[n]);
    if (ImGui::RadioButton(label, int(s.context) == n)) s.context = ContextShape(n);
    noteRect(rects, std::string("vg_context_") + kContextNames[n]);
  }
  // As many rows for every shape as for the slab's three sliders.
  if (s.context == ContextShape::slab) {
    sliderMm("in front (d1)", s.slab.frontMm, 0, 200);
    sliderMm("behind (d2)", s.slab.backMm, 0, 200);
    sliderMm("half width", s.slab.halfWidthMm, 5, 300);
  } else if (s.context == ContextShape::tube) {
    s.contextTube.mode = RadiusMode::constant;
    sliderMm("radius##context", s.contextTube.value, 1, 150);
    drawBlankWidgetRows(2);
  } else {
    drawBlankWidgetRows(3);
  }
}

void drawOutsideAndCuts(VesselGlyphState& set, WidgetRects& rects) {
  ImGui::TextUnformatted("outside");
  ImGui::SameLine();
  if (ImGui::RadioButton("clipped", !set.outsideRendered)) set.outsideRendered = false;
  ImGui::SameLine();
  if (ImGui::RadioButton("main TF", set.outsideRendered)) set.outsideRendered = true;
  noteRect(rects, "vg_outside_main");
  ImGui::Checkbox("foreground cleft", &set.settings.cleft);
  noteRect(rects, "vg_cleft");
  ImGui::SameLine();
  ImGui::Checkbox("half vessel", &set.settings.halfVessel);
  noteRect(rects, "vg_half_vessel");
}

}  // namespace

std::size_t centerlinePointCount(const Centerlines& centerlines) {
  std::size_t n = 0;
  for (const CenterlinePath& path : centerlines.paths) n += path.points.size();
  return n;
}

VesselGlyphPanelResult drawVesselGlyphPanel(const VesselGlyphState& state, VesselGlyphPanelUi& ui,
                                            const VesselGlyphPanelInfo& info, WidgetRects& rects) {
  VesselGlyphPanelResult result;
  drawLoading(ui, info, result, rects);
  if (!info.physical) return result;  // the rest once there are centerlines

  VesselGlyphState set = state;
  ImGui::Checkbox("VesselGlyph on", &set.enabled);
  noteRect(rects, "vg_enable");
  ImGui::SameLine();
  ImGui::Checkbox("centerline overlay", &set.overlay);
  noteRect(rects, "vg_overlay");
  drawFocus(set.settings.focus, rects);
  drawContext(set.settings, rects);
  drawOutsideAndCuts(set, rects);
  if (info.presets) {
    regionTfCombo("focus TF", TfTarget::focus, *info.presets, set.focusFollowsMain, set.focusTf,
                  set.focusPreset, result.message);
    regionTfCombo("context TF", TfTarget::context, *info.presets, set.contextFollowsMain, set.contextTf,
                  set.contextPreset, result.message);
  }
  ImGui::TextDisabled("edit them in the TF editor: \"TF editor edits\" above it");
  if (!(set == state)) result.edit = VesselGlyphEdit{std::move(set)};
  return result;
}

}  // namespace angio
