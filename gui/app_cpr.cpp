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
#include "gui/panel_cpr.h"
#include "io/tf_file.h"

namespace angio {

namespace {

constexpr float kCprShare = 0.35f;      // of the room left of the side panel
constexpr double kMaxCprPixelMm = 1.0;  // finer than coarse volumes' DVR pixels, for the ruler
constexpr float kClickReachPx = 12;     // a click this near a projected centerline moves the cursor

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
  if (cprViewWidth() <= 0 || !shown_ || !viewport_.hasImage) return;
  if (!ImGui::IsItemHovered() || !ImGui::IsMouseReleased(ImGuiMouseButton_Left)) return;
  const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.f);
  if (drag.x * drag.x + drag.y * drag.y > 9) return;  // a drag turns the view
  const Centerlines* centerlines = nullptr;
  try {
    centerlines = framedCenterlines();
  } catch (const std::exception&) {
    return;
  }
  const ViewGeometry& view = shownView_;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  float best = kClickReachPx * kClickReachPx;
  for (std::size_t p = 0; p < centerlines->paths.size(); ++p) {
    const CenterlinePath& path = centerlines->paths[p];
    const std::vector<double> arcs = arcLengthsMm(path);
    for (std::size_t n = 0; n < path.points.size(); ++n) {
      const ImVec2 at = dvrScreenOf(view, path.points[n].positionMm);
      const float dx = at.x - mouse.x, dy = at.y - mouse.y;
      if (dx * dx + dy * dy >= best) continue;
      best = dx * dx + dy * dy;
      cprView_.cursor = CenterlinePlace{int(p), arcs[n], path.points[n].positionMm};
    }
  }
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
      state.cpr.mode, state.cpr.path, state.cpr.coloring, std::nullopt};
  if (state.cpr.coloring == CprColoring::focusTf) inputs.focusTf = state.vesselGlyph.focusTf;
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
    Cpr cpr = computeCpr(volume, paths, geometry, CprSettings{inputs.mode, {}});
    CprDisplay display;
    if (inputs.coloring == CprColoring::calcium) display.windowLevel = kCalciumWindow;
    if (inputs.focusTf) display.tf = *inputs.focusTf;
    std::shared_ptr<const DisplayImage> image =
        makeDisplayImage(displayCpr(cpr.layout, cpr.hu, display));
    return ComputedCpr{inputs, std::move(cpr), std::move(image)};
  });
}

// A finished CPR replaces the shown one (uploaded at once: a CPR image is small).
void App::takeComputedCpr() {
  CprViewPanel& panel = cprView_;
  if (!panel.job.ready()) return;
  panel.hovered.reset();
  panel.madeFor = panel.computing;
  panel.computing.reset();
  try {
    ComputedCpr computed = panel.job.take();
    panel.frame = std::move(computed.image);
    panel.texture.begin(panel.frame);
    while (!panel.texture.step(std::size_t(64) << 20)) {
    }
    panel.cpr = std::move(computed.cpr);
    panel.error.clear();
  } catch (const std::exception& error) {
    panel.error = error.what();
    panel.cpr.reset();
    panel.frame.reset();
  }
}

// The CPR hovered: what it shows, and the same point marked on the DVR image.
void App::drawCprView() {
  CprViewPanel& panel = cprView_;
  panel.hovered.reset();
  panel.markedOnDvr.reset();
  const float width = cprViewWidth();
  if (width <= 0) return;
  updateCpr();
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
  const Rgb8Image& image = panel.frame->levels.front();
  const ImVec2 avail = ImGui::GetContentRegionAvail(), at = ImGui::GetCursorScreenPos();
  const float scale =
      std::max(std::min(avail.x / float(image.width), avail.y / float(image.height)), 1e-3f);
  const ImVec2 size(float(image.width) * scale, float(image.height) * scale);
  panel.imageMin = ImVec2(at.x + std::max(avail.x - size.x, 0.f) / 2, at.y);
  panel.imageMax = ImVec2(panel.imageMin.x + size.x, panel.imageMin.y + size.y);
  ImGui::SetCursorScreenPos(panel.imageMin);
  ImGui::InvisibleButton("cpr_image", ImVec2(std::max(size.x, 1.f), std::max(size.y, 1.f)));
  noteRect("cpr_image");
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddImage(panel.texture.id(), panel.imageMin, panel.imageMax);

  if (ImGui::IsItemHovered()) {
    const int x = int(std::floor((io.MousePos.x - panel.imageMin.x) / scale));
    const int y = int(std::floor((io.MousePos.y - panel.imageMin.y) / scale));
    panel.hovered = pickCpr(*panel.cpr, x, y);
    const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.f);
    if (panel.hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
        drag.x * drag.x + drag.y * drag.y <= 9)
      traceOnCprClick(*panel.hovered);
  }
  char text[128];
  if (panel.hovered)
    std::snprintf(text, sizeof text, "arc %.1f mm   %.0f HU   path %d", panel.hovered->arcMm,
                  double(panel.hovered->hu), panel.hovered->path);
  else std::snprintf(text, sizeof text, "hover the CPR: arc length, HU");
  draw->AddText(hoverLine, panel.hovered ? IM_COL32(255, 230, 90, 255) : IM_COL32(150, 150, 150, 255),
                text);
  panel.cursorPixel.reset();
  if (panel.cursor && (cprState.path < 0 || cprState.path == panel.cursor->path))
    panel.cursorPixel =
        cprPixelOf(panel.cpr->layout, cprState.path < 0 ? panel.cursor->path : 0, panel.cursor->arcMm);
  if (panel.cursorPixel) {
    const ImVec2 mark(panel.imageMin.x + float(panel.cursorPixel->x + 0.5) * scale,
                      panel.imageMin.y + float(panel.cursorPixel->y + 0.5) * scale);
    draw->AddCircle(mark, 7, IM_COL32(90, 255, 120, 255), 0, 2);
    draw->AddLine(ImVec2(panel.imageMin.x, mark.y), ImVec2(mark.x - 8, mark.y),
                  IM_COL32(90, 255, 120, 160));
    draw->AddLine(ImVec2(mark.x + 8, mark.y), ImVec2(panel.imageMax.x, mark.y),
                  IM_COL32(90, 255, 120, 160));
  }
  if (shown_ && viewport_.hasImage) {  // the hovered point (yellow) and the cursor (green) on the DVR
    const ViewGeometry& shownView = shownView_;
    ImDrawList* front = ImGui::GetForegroundDrawList();
    front->PushClipRect(viewport_.min, viewport_.max, true);
    if (panel.cursor)
      front->AddCircle(dvrScreenOf(shownView, panel.cursor->pointMm), 7, IM_COL32(90, 255, 120, 255), 0,
                       2);
    if (panel.hovered) {
      panel.markedOnDvr = dvrScreenOf(shownView, panel.hovered->pointMm);
      front->AddCircle(*panel.markedOnDvr, 7, IM_COL32(255, 230, 90, 255), 0, 2);
    }
    front->PopClipRect();
  }
  ImGui::End();
}

}  // namespace angio
