#include "gui/panel_clip.h"

#include <algorithm>
#include <string>

#include <imgui.h>

namespace angio {

namespace {

constexpr const char* kAxisNames[] = {"i", "j", "k"};
constexpr float kSliderWidth = 260;

// A double slider over [lo, hi], noted as `name`.
bool slider(const char* label, double& value, double lo, double hi, const char* format,
            const std::string& name, WidgetRects& rects) {
  ImGui::SetNextItemWidth(kSliderWidth);
  const bool changed = ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &lo, &hi, format,
                                           ImGuiSliderFlags_AlwaysClamp);
  noteRect(rects, name);
  return changed;
}

bool checkbox(const char* label, bool& value, const std::string& name, WidgetRects& rects) {
  const bool changed = ImGui::Checkbox(label, &value);
  noteRect(rects, name);
  return changed;
}

// A part's on/off checkbox with its help; returns whether the part is on (its widgets follow).
bool partSwitch(const char* label, bool& on, const std::string& name, const char* help,
                WidgetRects& rects) {
  checkbox(label, on, name, rects);
  helpMarker(help);
  return on;
}

// Min and max per axis; dragging one past the other moves the other along, so the box is never
// empty.
void drawCrop(ClipState& clip, glm::dvec3 extent, WidgetRects& rects) {
  const bool wasOn = clip.cropOn;
  if (!partSwitch("crop box", clip.cropOn, "clip_crop",
                  "Render only the box between the six planes (mm of the volume frame, voxel axes).",
                  rects))
    return;
  if (!wasOn && clip.crop == CropBox{}) clip.crop = CropBox{glm::dvec3(0.0), extent};
  for (int axis = 0; axis < 3; ++axis) {
    const std::string axisName = kAxisNames[axis], name = "clip_crop_" + axisName;
    double& lo = clip.crop.minMm[axis];
    double& hi = clip.crop.maxMm[axis];
    if (slider((axisName + " min").c_str(), lo, 0, extent[axis], "%.1f mm", name + "_min", rects))
      hi = std::max(hi, lo);
    if (slider((axisName + " max").c_str(), hi, 0, extent[axis], "%.1f mm", name + "_max", rects))
      lo = std::min(lo, hi);
  }
}

// The normal's widgets: a voxel axis, flipped, the current view's direction, or any direction by
// its azimuth and elevation.
void drawNormal(ClipState& clip, glm::dvec3 towardsViewer, WidgetRects& rects) {
  ImGui::TextUnformatted("normal");
  for (int axis = 0; axis < 3; ++axis) {
    ImGui::SameLine();
    if (ImGui::Button((std::string(kAxisNames[axis]) + "##clip_normal").c_str())) {
      clip.normal = glm::dvec3(0.0);
      clip.normal[axis] = 1;
    }
    noteRect(rects, std::string("clip_normal_") + kAxisNames[axis]);
  }
  ImGui::SameLine();
  if (ImGui::Button("flip##clip")) clip.normal = -clipNormalOf(clip);
  noteRect(rects, "clip_flip");
  ImGui::SameLine();
  if (ImGui::Button("from view##clip")) clip.normal = glm::normalize(towardsViewer);
  noteRect(rects, "clip_from_view");
  helpMarker(
      "The normal points to the side that is removed. From view: towards you as the view "
      "is now, so the plane removes what lies in front of it.");
  glm::dvec2 angles = anglesOfNormal(clipNormalOf(clip));
  const bool azimuth = slider("azimuth", angles.x, -180, 180, "%.1f deg", "clip_azimuth", rects);
  const bool elevation = slider("elevation", angles.y, -90, 90, "%.1f deg", "clip_elevation", rects);
  if (azimuth || elevation) clip.normal = normalFromAngles(angles);
}

void drawPlane(ClipState& clip, glm::dvec3 extent, glm::dvec3 towardsViewer, WidgetRects& rects) {
  if (!partSwitch("clip plane", clip.planeOn, "clip_plane",
                  "Remove the half-space on the plane's normal side. Facing the viewer: what lies "
                  "in front of the plane (it turns with the view); Fix keeps that cut in the "
                  "volume as the view turns.",
                  rects))
    return;
  ImGui::Indent();
  checkbox("facing the viewer", clip.facingViewer, "clip_facing", rects);
  double reach = glm::length(extent) / 2;
  if (clip.facingViewer) {
    ImGui::SameLine();
    if (ImGui::Button("fix##clip")) clip = fixedToView(clip, towardsViewer);
    noteRect(rects, "clip_fix");
  }
  if (!clip.facingViewer) {
    drawNormal(clip, towardsViewer, rects);
    reach = planeReachMm(clipNormalOf(clip), extent);
  }
  slider("offset##plane", clip.planeOffsetMm, -reach, reach, "%.1f mm", "clip_plane_offset", rects);
  ImGui::Unindent();
}

void drawSlab(ClipState& clip, glm::dvec3 extent, WidgetRects& rects) {
  if (!partSwitch("thick slab", clip.slabOn, "clip_slab",
                  "Render only a slab facing the viewer: its depth from the volume centre "
                  "(positive: away from the viewer) and thickness, DVR or MIP as the Rendering "
                  "section says.",
                  rects))
    return;
  const double reach = glm::length(extent) / 2;
  ImGui::Indent();
  slider("offset##slab", clip.slab.offsetMm, -reach, reach, "%.1f mm", "clip_slab_offset", rects);
  slider("thickness", clip.slab.thicknessMm, 1, 2 * reach, "%.1f mm", "clip_slab_thickness", rects);
  ImGui::Unindent();
}

}  // namespace

std::optional<ClipEdit> drawClipPanel(const ClipState& clip, glm::dvec3 extentMm,
                                      glm::dvec3 towardsViewer, WidgetRects& rects) {
  ClipState edited = clip;
  drawCrop(edited, extentMm, rects);
  drawPlane(edited, extentMm, towardsViewer, rects);
  drawSlab(edited, extentMm, rects);
  if (ImGui::Button("reset##clip")) edited = {};
  noteRect(rects, "clip_reset");
  if (edited == clip) return std::nullopt;
  return ClipEdit{edited};
}

}  // namespace angio
