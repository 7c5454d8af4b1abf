// The CPR view of App (thesis sec. 5.2.2, fig. 5.4): the curved planar
// reformation of the selected path beside the DVR view, at the view's axis and angle (so rotating
// the view turns the straightened CPR's vector of interest). Hovering it shows the arc length and
// HU under the mouse and marks that point on the DVR image.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include <imgui.h>

#include "core/view_geometry.h"
#include "gui/app.h"
#include "gui/cpr_pane.h"
#include "gui/slice_pane.h"
#include "gui/viewport.h"
#include "gui/zoom_pan.h"
#include "gui/panel_cpr.h"
#include "io/tf_file.h"

namespace angio {

namespace {

constexpr float kCprShare = 0.35f;      // of the room left of the side panel
constexpr double kMaxCprPixelMm = 1.0;  // finer than coarse volumes' DVR pixels, for the ruler
constexpr float kClickReachPx = 12;     // a click this near a projected centerline moves the cursor
constexpr double kRulerOffsetMm = 15;   // the ruler beside the lumen: past an aorta's radius
constexpr double kInsetExtentMm = 40, kInsetPixelMm = 0.5;  // the cross-section: an aorta and its wall

ImVec2 toIm(glm::dvec2 p) { return {float(p.x), float(p.y)}; }

// Where a centerline point lies in the CPR image: on its path's curve, or, on a trunk the path
// shares with an earlier path (drawn once, vessel/cpr_layout.h), on that path's curve.
// `path` indexes the paths the CPR was computed for.
std::optional<glm::dvec2> cprPixelOf(const CprLayout& layout, int path, double arcMm) {
  for (const bool samePath : {true, false}) {
    for (const CprCurve& curve : layout.curves) {
      if (samePath ? curve.path != path : curve.path >= path) continue;
      for (std::size_t n = 1; n < curve.arcMm.size(); ++n) {
        const double a0 = curve.arcMm[n - 1], a1 = curve.arcMm[n];
        if (arcMm < a0 || arcMm > a1) continue;
        const double f = a1 > a0 ? (arcMm - a0) / (a1 - a0) : 0;
        return curve.pixels[n - 1] + f * (curve.pixels[n] - curve.pixels[n - 1]);
      }
    }
  }
  return std::nullopt;
}

}  // namespace

// A left click (not a drag) on the DVR image near a projected centerline: the nearest centerline
// point becomes the CPR view's cursor.
void App::moveCprCursorOnClick() {
  if (cprViewWidth() <= 0 || !clickedImagePoint()) return;
  const Centerlines* centerlines = cprCenterlines();
  if (!centerlines) return;
  const ViewGeometry& view = shownView_;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  float best = kClickReachPx * kClickReachPx;
  std::optional<CprCursor> nearest;
  for (std::size_t p = 0; p < centerlines->paths.size(); ++p) {
    const CenterlinePath& path = centerlines->paths[p];
    const std::vector<double> arcs = arcLengthsMm(path);
    for (std::size_t n = 0; n < path.points.size(); ++n) {
      const ImVec2 at = dvrScreenOf(view, path.points[n].positionMm);
      const float dx = at.x - mouse.x, dy = at.y - mouse.y;
      if (dx * dx + dy * dy >= best) continue;
      best = dx * dx + dy * dy;
      nearest = CprCursor{int(p), arcs[n]};
    }
  }
  if (nearest) setCprCursor(*nearest);
}

// The document's cursor on the centerlines it indexes, or none: no cursor, no centerlines, or a
// path that is not there (any more) or too short; the arc length clamped to the path.
std::optional<CenterlinePlace> App::cprCursorPlace() {
  const std::optional<CprCursor>& cursor = doc().cpr.cursor;
  const Centerlines* centerlines = cprCenterlines();
  if (!cursor || !centerlines || cursor->path < 0 || cursor->path >= int(centerlines->paths.size()) ||
      centerlines->paths[cursor->path].points.size() < 2)
    return std::nullopt;
  const CenterlinePath& path = centerlines->paths[cursor->path];
  const double arcMm = std::clamp(cursor->arcMm, 0.0, arcLengthsMm(path).back());
  return CenterlinePlace{cursor->path, arcMm, placeOnPath(path, arcMm).pointMm};
}

void App::setCprCursor(CprCursor cursor) {
  CprState cpr = doc().cpr;
  cpr.cursor = cursor;
  commit(CprEdit{cpr});
}

// Up/Down (Shift: 10 mm) move the cursor 1 mm along its path, towards its end or its start; the
// slices follow (one 3-D cursor).
void App::stepCprCursor(double mm) {
  if (cprViewWidth() <= 0) return;
  const std::optional<CenterlinePlace> place = cprCursorPlace();
  if (!place) return;
  const double lengthMm = arcLengthsMm(cprCenterlines()->paths[place->path]).back();
  setCprCursor(CprCursor{place->path, std::clamp(place->arcMm + mm, 0.0, lengthMm)});
  if (const std::optional<CenterlinePlace> moved = cprCursorPlace()) moveSliceCursor(moved->pointMm);
}

float App::cprViewWidth() const {
  if (!doc().cpr.shown || !vessel_.physical) return 0;
  return std::floor(std::max(ImGui::GetIO().DisplaySize.x - kPanelWidth, 0.f) * kCprShare);
}

void App::drawCprSection() {
  if (!vessel_.physical || !sectionHeader("CPR")) return;  // the section needs centerlines
  const CprPanelInfo info{&*vessel_.physical, doc().vesselGlyph.enabled, cprView_.error,
                          vessel_.hybridProblem};
  commit(drawCprPanel(doc().cpr, info, widgetRects_));
}

// Recomputes the CPR when its inputs changed (not while a slider or a spin changes them every
// frame, once one is shown), and uploads it as the view's texture.
// The CPR of the document's path, view and coloring, computed off the UI thread; while a drag or
// a spin goes on the shown CPR stays (it follows when the view rests).
void App::updateCpr() {
  CprViewPanel& panel = cprView_;
  takeComputedCpr();
  const Centerlines* centerlines = nullptr;
  try {
    centerlines = framedCenterlines();
  } catch (const std::exception& error) {
    panel.error = error.what();
  }
  if (!centerlines) return;
  loadMissingRegionTfs();
  const Document& state = doc();
  CprInputs inputs{
      vessel_.framedFor, vessel_.file, vessel_.revision, state.view.axis, state.view.angleDeg,
      // The high level's pixel size, so a projected CPR registers with the DVR image.
      std::min(state.levels[int(Quality::high)].isd * voxelUnit(data_.volume), kMaxCprPixelMm),
      state.cpr.mode, state.cpr.path, std::nullopt};
  if (state.cpr.mode != CprMode::projected) inputs.widthMm = state.cpr.widthMm;
  if (inputs == panel.madeFor || panel.job.running()) return;  // one at a time: the next one after it
  if (panel.cpr && (ImGui::IsAnyItemActive() || state.view.autoSpin)) return;
  panel.computing = inputs;
  std::vector<CenterlinePath> paths;
  try {
    paths = selectPaths(*centerlines, state.cpr.path < 0 ? "all" : std::to_string(state.cpr.path));
  } catch (const std::exception& error) {
    panel.job.stop();
    panel.computing.reset();
    panel.madeFor = inputs;
    panel.error = error.what();
    panel.cpr.reset();
    panel.frame.reset();
    return;
  }
  panel.job.start([&volume = data_.volume, inputs, paths = std::move(paths)](JobControl&) {
    const ViewGeometry geometry = cprView(volume, inputs.axis, inputs.angleDeg, inputs.pixelMm);
    return ComputedCpr{inputs,
                       computeCpr(volume, paths, geometry, CprSettings{inputs.mode, inputs.widthMm})};
  });
}

// A finished CPR replaces the shown one (colored and uploaded by showCprLook).
void App::takeComputedCpr() {
  CprViewPanel& panel = cprView_;
  if (!panel.job.ready()) return;
  panel.hovered.reset();
  panel.madeFor = panel.computing;
  panel.computing.reset();
  panel.look.reset();
  try {
    panel.cpr = panel.job.take().cpr;
    panel.error.clear();
  } catch (const std::exception& error) {
    panel.error = error.what();
    panel.cpr.reset();
    panel.frame.reset();
  }
}

CprLook App::cprLook() const {
  CprLook look{doc().cpr.window, std::nullopt};
  if (doc().cpr.coloring == CprColoring::focusTf) look.focusTf = tfOf(doc(), TfTarget::focus);
  return look;
}

// The shown CPR colored as the section says, made here (a few hundred thousand pixels at most,
// well under a frame) so a window drag follows the hand; uploaded at once.
void App::showCprLook() {
  CprViewPanel& panel = cprView_;
  const CprLook look = cprLook();
  if (!panel.cpr || panel.look == look) return;
  CprDisplay display{look.window, look.focusTf};
  display.ruler = false;  // the pane draws its own beside the lumen, crisp at any zoom
  panel.frame = makeDisplayImage(displayCpr(panel.cpr->layout, panel.cpr->hu, display));
  panel.texture.begin(panel.frame);
  while (!panel.texture.step(std::size_t(64) << 20)) {
  }
  panel.look = look;
}

// The pane's gestures, right after its button: the wheel zooms about the pointer, a left or middle
// drag pans, a right drag sets the window, a double click fits the image again; a left click (no
// drag) puts the cursor on the centerline of the line clicked, or with the trace tool adds a point.
void App::handleCprMouse(const CprPlacement& placement) {
  CprViewPanel& panel = cprView_;
  const ImGuiIO& io = ImGui::GetIO();
  CprState cpr = doc().cpr;
  if (ImGui::IsItemActive()) panel.held = true;
  if (ImGui::IsItemHovered() && io.MouseWheel != 0)
    zoomAboutPointer(cpr.zoom, cpr.panPx, glm::dvec2(io.MousePos.x, io.MousePos.y) - placement.home,
                     io.MouseWheel, kMinCprZoom, kMaxCprZoom);
  // As in the 3-D view, the press's frame moves nothing (its delta is the way to the press point).
  if (ImGui::IsItemActive() && !ImGui::IsItemActivated() &&
      (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 3) || ImGui::IsMouseDown(ImGuiMouseButton_Middle)))
    cpr.panPx += glm::dvec2(io.MouseDelta.x, io.MouseDelta.y);
  if (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
    if (!panel.windowAtPress) panel.windowAtPress = cpr.window;
    const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Right, 0.f);
    cpr.window = draggedWindowLevel(*panel.windowAtPress, {drag.x, drag.y});
  }
  if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) fitCprPane(cpr);
  if (!(cpr == doc().cpr)) commit(CprEdit{cpr});

  if (!ImGui::IsItemHovered()) return;
  const glm::ivec2 pixel = cprPixelUnder(placement, {io.MousePos.x, io.MousePos.y});
  panel.hovered = pickCpr(*panel.cpr, pixel.x, pixel.y);
  const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.f);
  if (!panel.hovered || !ImGui::IsMouseReleased(ImGuiMouseButton_Left) ||
      drag.x * drag.x + drag.y * drag.y > 9)
    return;
  if (vessels_.ui.traceTool) traceOnCprClick(*panel.hovered);
  else moveCprCursorTo(*panel.hovered);
}

// The centerlines in the volume frame, or null: none loaded, or they no longer fit the volume
// (updateCpr shows why); the CPR shown may be older than that.
const Centerlines* App::cprCenterlines() {
  try {
    return framedCenterlines();
  } catch (const std::exception&) {
    return nullptr;
  }
}

// The clicked line's centerline point is the cursor, in the CPR, on the DVR image and in the
// slices (one 3-D cursor).
void App::moveCprCursorTo(const CprPick& pick) {
  const Centerlines* centerlines = cprCenterlines();
  const int path = doc().cpr.path < 0 ? pick.path : doc().cpr.path;
  if (!centerlines || path < 0 || path >= int(centerlines->paths.size()) ||
      centerlines->paths[path].points.size() < 2)
    return;
  setCprCursor(CprCursor{path, pick.arcMm});
  moveSliceCursor(placeOnPath(centerlines->paths[path], pick.arcMm).pointMm);
}

// Ticks every rulerStepMm beside the lumen (kRulerOffsetMm off the centerline, on its left in
// the image), labelled every fifth, and each path's name at its far end.
void App::drawCprRuler(const CprPlacement& placement) {
  const Cpr& cpr = *cprView_.cpr;
  const double screenPerMm = placement.scale / cpr.layout.pixelMm;
  const double offsetMm = std::min(kRulerOffsetMm, 0.3 * cpr.layout.widthMm);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImU32 color = IM_COL32(255, 217, 26, 255);
  for (const CprRulerTick& tick : cprRulerTicks(cpr.layout.curves, rulerStepMm(screenPerMm))) {
    const glm::dvec2 at = screenOfCprPixel(placement, tick.pixel) + offsetMm * screenPerMm * tick.across;
    const double length = tick.major ? 9 : 4;
    draw->AddLine(toIm(at), toIm(at + length * tick.across), color, 1.5f);
    if (!tick.major) continue;
    char label[32];
    std::snprintf(label, sizeof label, "%.0f", tick.arcMm);
    const ImVec2 size = ImGui::CalcTextSize(label);
    const glm::dvec2 end = at + (length + 3) * tick.across;
    textWithShadow(draw,
                   ImVec2(float(end.x) - (tick.across.x < 0 ? size.x : 0), float(end.y) - size.y / 2),
                   color, label);
  }
  const Centerlines* centerlines = cprCenterlines();
  for (const CprCurve& curve : cpr.layout.curves) {
    const int path = doc().cpr.path < 0 ? curve.path : doc().cpr.path;
    if (!centerlines || curve.pixels.empty() || path >= int(centerlines->paths.size())) continue;
    const std::string& name = centerlines->paths[path].name;
    const std::string label = name.empty() ? "path " + std::to_string(path) : name;
    const glm::dvec2 end = screenOfCprPixel(placement, curve.pixels.back());
    textWithShadow(draw, ImVec2(float(end.x) + 6, float(end.y) - ImGui::GetTextLineHeight() - 4),
                   IM_COL32(230, 230, 230, 255), label.c_str());
  }
}

// The cursor on the CPR: a ring and a line across the image at its arc length.
void App::drawCprCursor(const CprPlacement& placement, ImVec2 paneMin, ImVec2 paneMax) {
  CprViewPanel& panel = cprView_;
  const CprState& state = doc().cpr;
  panel.cursorPixel.reset();
  const std::optional<CenterlinePlace> cursor = cprCursorPlace();
  if (cursor && (state.path < 0 || state.path == cursor->path))
    panel.cursorPixel = cprPixelOf(panel.cpr->layout, state.path < 0 ? cursor->path : 0, cursor->arcMm);
  if (!panel.cursorPixel) return;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 mark = toIm(screenOfCprPixel(placement, *panel.cursorPixel));
  const ImU32 green = IM_COL32(90, 255, 120, 255), faint = IM_COL32(90, 255, 120, 160);
  draw->AddCircle(mark, 7, green, 0, 2);
  draw->AddLine(ImVec2(paneMin.x, mark.y), ImVec2(mark.x - 8, mark.y), faint);
  draw->AddLine(ImVec2(mark.x + 8, mark.y), ImVec2(paneMax.x, mark.y), faint);
}

// The section perpendicular to the path at the cursor, in the pane's lower right corner, colored
// as the CPR; image up is the DVR view's up (towards the viewer for a vessel along it).
void App::drawCrossSectionInset(ImVec2 paneMin, ImVec2 paneMax) {
  CprViewPanel& panel = cprView_;
  CrossSectionInset& inset = panel.inset;
  const std::optional<CenterlinePlace> cursor = cprCursorPlace();
  if (!cursor || !panel.cursorPixel) return;
  const std::pair<CenterlinePlace, CprLook> wanted{*cursor, cprLook()};
  if (inset.madeFor != wanted) {
    const PathPlace place = placeOnPath(cprCenterlines()->paths[cursor->path], cursor->arcMm);
    const glm::dvec3 up = shownView_.up, towardsViewer = -shownView_.viewDir;
    const glm::dvec3 hint = std::abs(glm::dot(place.tangent, up)) < 0.7 ? up : towardsViewer;
    const CrossSection section = sampleCrossSection(data_.volume, place.pointMm, place.tangent, hint,
                                                    kInsetExtentMm, kInsetPixelMm);
    // Colored as the CPR; outside the volume black.
    inset.texture.begin(
        makeDisplayImage(coloredHu(section.size, section.size, section.hu,
                                   CprDisplay{wanted.second.window, wanted.second.focusTf})));
    while (!inset.texture.step(std::size_t(16) << 20)) {
    }
    inset.madeFor = wanted;
  }
  const float side = std::floor(std::min(paneMax.x - paneMin.x, paneMax.y - paneMin.y) * 0.4f);
  if (side < 48) return;
  const ImVec2 max(paneMax.x - 6, paneMax.y - 6), min(max.x - side, max.y - side);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddImage(inset.texture.id(), min, max);
  draw->AddRect(ImVec2(min.x - 1, min.y - 1), ImVec2(max.x + 1, max.y + 1), IM_COL32(90, 255, 120, 255));
  const ImVec2 centre((min.x + max.x) / 2, (min.y + max.y) / 2);
  const ImU32 mark = IM_COL32(90, 255, 120, 200);
  for (const float sign : {-1.f, 1.f}) {  // a crosshair with a gap over the lumen's centre
    draw->AddLine(ImVec2(centre.x + sign * 6, centre.y), ImVec2(centre.x + sign * 14, centre.y), mark);
    draw->AddLine(ImVec2(centre.x, centre.y + sign * 6), ImVec2(centre.x, centre.y + sign * 14), mark);
  }
  char caption[48];
  std::snprintf(caption, sizeof caption, "section %.0f mm", kInsetExtentMm);
  textWithShadow(draw, ImVec2(min.x + 4, min.y + 2), IM_COL32(230, 230, 230, 255), caption);
  noteRect("cpr_section", min, max);
}

// The pane: the CPR at its zoom and pan with the ruler, names, cursor and cross-section; hovering
// reads arc length and HU and marks the point on the DVR image.
void App::drawCprView() {
  CprViewPanel& panel = cprView_;
  panel.hovered.reset();
  panel.markedOnDvr.reset();
  panel.held = false;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Right)) panel.windowAtPress.reset();
  const float width = cprViewWidth();
  if (width <= 0) return;
  updateCpr();
  showCprLook();
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(std::max(io.DisplaySize.x - kPanelWidth - width, 64.f), 0));
  ImGui::SetNextWindowSize(ImVec2(width, std::max(io.DisplaySize.y - kStatusHeight, 64.f)));
  ImGui::Begin("##cpr", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
  const CprState& cprState = doc().cpr;
  ImGui::Text("CPR %s, %s", toString(cprState.mode),
              cprPathLabel(*vessel_.physical, cprState.path).c_str());
  const ImVec2 hoverLine = ImGui::GetCursorScreenPos();
  ImGui::NewLine();
  if (!panel.error.empty()) ImGui::TextWrapped("%s", panel.error.c_str());
  if (!panel.frame || !panel.cpr || panel.texture.empty()) {
    ImGui::End();
    return;
  }
  const ImVec2 paneMin = ImGui::GetCursorScreenPos();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const ImVec2 paneMax(paneMin.x + std::max(avail.x, 16.f), paneMin.y + std::max(avail.y, 16.f));
  const glm::ivec2 imageSize{panel.cpr->layout.width, panel.cpr->layout.height};
  ImGui::InvisibleButton("cpr_pane", ImVec2(paneMax.x - paneMin.x, paneMax.y - paneMin.y),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  noteRect("cpr_pane");
  const glm::dvec2 panePx{paneMin.x, paneMin.y}, paneSize{paneMax.x - paneMin.x, paneMax.y - paneMin.y};
  handleCprMouse(placeCpr(imageSize, panePx, paneSize, doc().cpr.zoom, doc().cpr.panPx));
  // Placed again with this frame's zoom and pan, so the image follows the gesture at once.
  const CprPlacement placement = placeCpr(imageSize, panePx, paneSize, doc().cpr.zoom, doc().cpr.panPx);
  panel.imageMin = toIm(placement.min);
  panel.imageMax = toIm(placement.min + glm::dvec2(imageSize) * placement.scale);
  noteRect("cpr_image", panel.imageMin, panel.imageMax);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(paneMin, paneMax, true);
  draw->AddImage(panel.texture.id(), panel.imageMin, panel.imageMax);
  drawCprRuler(placement);
  drawCprCursor(placement, paneMin, paneMax);
  drawCrossSectionInset(paneMin, paneMax);
  draw->PopClipRect();

  char text[128];
  if (panel.hovered)
    std::snprintf(text, sizeof text, "arc %.1f mm   %.0f HU   path %d", panel.hovered->arcMm,
                  double(panel.hovered->hu), panel.hovered->path);
  else std::snprintf(text, sizeof text, "hover the CPR: arc length, HU");
  draw->AddText(hoverLine, panel.hovered ? IM_COL32(255, 230, 90, 255) : IM_COL32(150, 150, 150, 255),
                text);
  markCprOnDvr();
  ImGui::End();
}

// The hovered point (yellow) and the cursor (green) on the DVR image.
void App::markCprOnDvr() {
  CprViewPanel& panel = cprView_;
  if (!shown_ || !viewport_.hasImage) return;
  ImDrawList* front = ImGui::GetForegroundDrawList();
  front->PushClipRect(viewport_.min, viewport_.max, true);
  if (const std::optional<CenterlinePlace> cursor = cprCursorPlace())
    front->AddCircle(dvrScreenOf(shownView_, cursor->pointMm), 7, IM_COL32(90, 255, 120, 255), 0, 2);
  if (panel.hovered) {
    panel.markedOnDvr = dvrScreenOf(shownView_, panel.hovered->pointMm);
    front->AddCircle(*panel.markedOnDvr, 7, IM_COL32(255, 230, 90, 255), 0, 2);
  }
  front->PopClipRect();
}

}  // namespace angio
