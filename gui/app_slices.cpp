// The linked slice view of App: axial, coronal and sagittal slices through the 3-D cursor in a
// column beside the image, grey through the document's window/level, radiological (the patient's
// right on the left, superior up). A click or drag in a slice moves the cursor there, the wheel
// steps through slices, a right-drag sets window/level; a click on the image (no tool on) puts the
// cursor on the visible surface under it, from the same pick the tools use. Each slice shows the
// other two as a crosshair and the centerlines where they cross it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include <imgui.h>

#include "gui/app.h"
#include "gui/panel_slices.h"
#include "gui/zoom_pan.h"

namespace angio {

namespace {

constexpr float kSliceShare = 0.3f;  // of the room left of the side panel
constexpr std::array<SliceOrientation, 3> kOrientations{
    SliceOrientation::axial, SliceOrientation::coronal, SliceOrientation::sagittal};

// Each plane's color, as its crosshair line in the other slices shows it (Slicer's: axial red,
// coronal green, sagittal yellow).
ImU32 planeColor(SliceOrientation orientation, int alpha = 255) {
  switch (orientation) {
    case SliceOrientation::axial: return IM_COL32(235, 90, 80, alpha);
    case SliceOrientation::coronal: return IM_COL32(100, 210, 100, alpha);
    case SliceOrientation::sagittal: return IM_COL32(235, 205, 70, alpha);
  }
  return IM_COL32(255, 255, 255, alpha);
}

// The slice whose fixed axis is the voxel axis `axis`.
SliceOrientation planeOfAxis(int axis) {
  for (SliceOrientation o : kOrientations)
    if (fixedAxisOf(o) == axis) return o;
  return SliceOrientation::axial;
}

std::shared_ptr<const DisplayImage> displayOf(const SliceImage& slice) {
  Rgb8Image image{slice.width, slice.height, {}};
  image.rgb.resize(slice.grey.size() * 3);
  for (std::size_t n = 0; n < slice.grey.size(); ++n)
    image.rgb[3 * n] = image.rgb[3 * n + 1] = image.rgb[3 * n + 2] = slice.grey[n];
  auto display = std::make_shared<DisplayImage>();
  display->levels.push_back(image);
  for (Rgb8Image& level : halvedLevels(image)) display->levels.push_back(std::move(level));
  return display;
}

ImVec2 toIm(glm::dvec2 p) { return {float(p.x), float(p.y)}; }

}  // namespace

glm::dvec3 App::sliceCursor() const {
  return doc().slices.cursorMm ? clampToVolume(data_.volume, *doc().slices.cursorMm)
                               : domainExtent(data_.volume) * 0.5;
}

float App::sliceViewWidth() const {
  if (!doc().slices.shown) return 0;
  return std::floor(std::max(ImGui::GetIO().DisplaySize.x - kPanelWidth, 0.f) * kSliceShare);
}

void App::resetSliceView() {
  for (SlicePaneUi& pane : slices_.panes) pane.shown.reset();
  slices_.windowLevelAtPress.reset();
  slices_.hoveredVoxel.reset();
}

void App::drawSlicesSection() {
  if (!sectionHeader("Slices", false)) return;
  const glm::dvec3 cursor = sliceCursor();
  const glm::ivec3 voxel = cursorVoxel(data_.volume, cursor);
  const SlicesPanelInfo info{cursor, voxel, data_.volume.dims,
                             huOfDensity(data_.volume.densityAt(voxel.x, voxel.y, voxel.z))};
  commit(drawSlicesPanel(doc().slices, info, widgetRects_));
}

void App::moveSliceCursor(glm::dvec3 cursorMm) {
  SliceViewState slices = doc().slices;
  slices.cursorMm = clampToVolume(data_.volume, cursorMm);
  commit(SliceViewEdit{slices});
}

// A click (not a drag) on the image with no tool on: the visible point under it is the cursor.
void App::moveSliceCursorOnClick() {
  if (!doc().slices.shown || vessels_.ui.traceTool || labels_.ui.growTool) return;
  const std::optional<glm::dvec2> imagePoint = clickedImagePoint();
  if (!imagePoint) return;
  if (const std::optional<PickedPoint> picked = pickVisible(*imagePoint))
    moveSliceCursor(picked->positionMm);
  else message_ = "nothing visible under the cursor: the slices stay";
}

// The cursor on the image: a small cross in a ring.
void App::drawSliceCursorOnImage() {
  if (!doc().slices.shown || !shown_ || !viewport_.hasImage) return;
  const ImVec2 at = dvrScreenOf(shownView_, sliceCursor());
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(viewport_.min, viewport_.max, true);
  const ImU32 color = IM_COL32(255, 150, 40, 255);
  draw->AddCircle(at, 6, color, 0, 1.5f);
  draw->AddLine(ImVec2(at.x - 11, at.y), ImVec2(at.x - 3, at.y), color, 1.5f);
  draw->AddLine(ImVec2(at.x + 3, at.y), ImVec2(at.x + 11, at.y), color, 1.5f);
  draw->AddLine(ImVec2(at.x, at.y - 11), ImVec2(at.x, at.y - 3), color, 1.5f);
  draw->AddLine(ImVec2(at.x, at.y + 3), ImVec2(at.x, at.y + 11), color, 1.5f);
  draw->PopClipRect();
}

// The slice of `orientation` through the cursor, extracted and uploaded when its index or the
// window/level changed (a slice is small: it goes up in one frame).
void App::updateSliceTexture(SliceOrientation orientation) {
  SlicePaneUi& pane = slices_.panes[int(orientation)];
  const glm::dvec3 cursor = sliceCursor();
  const ShownSlice wanted{cursorVoxel(data_.volume, cursor)[fixedAxisOf(orientation)],
                          doc().slices.windowLevel};
  if (pane.shown == wanted && !pane.texture.empty()) return;
  const SliceImage slice = extractSlice(data_.volume, orientation, cursor, wanted.windowLevel);
  pane.texture.begin(displayOf(slice));
  while (!pane.texture.step(std::size_t(64) << 20)) {
  }
  pane.shown = wanted;
  pane.size = {slice.width, slice.height};
}

// One slice in the rectangle at `min` of `size`: its title line, the image, crosshair, letters,
// centerline crossings; then what the mouse does there.
void App::drawSlicePane(SliceOrientation orientation, ImVec2 min, ImVec2 size,
                        const Centerlines* centerlines) {
  SlicePaneUi& pane = slices_.panes[int(orientation)];
  const Volume& volume = data_.volume;
  const glm::dvec3 cursor = sliceCursor();
  const int axis = fixedAxisOf(orientation);
  const int index = cursorVoxel(volume, cursor)[axis];
  ImDrawList* draw = ImGui::GetWindowDrawList();
  char title[96];
  std::snprintf(title, sizeof title, "%s  %c %d/%d  %.1f mm", sliceOrientationName(orientation),
                "ijk"[axis], index, volume.dims[axis] - 1, index * volume.spacing[axis]);
  draw->AddText(min, planeColor(orientation), title);
  const float titleHeight = ImGui::GetTextLineHeightWithSpacing();
  const glm::dvec2 imageArea(size.x, std::max(size.y - titleHeight, 1.f));
  updateSliceTexture(orientation);
  const glm::dvec2 areaMin{min.x, min.y + titleHeight};
  const auto place = [&] {
    const SlicePaneView& view = doc().slices.panes[int(orientation)];
    return placeSlice(pane.size, sliceSpacingMm(volume, orientation), areaMin, imageArea, view.zoom,
                      view.panPx);
  };
  pane.placement = place();
  const ImVec2 paneMin = toIm(areaMin), paneMax = toIm(areaMin + imageArea);
  ImGui::SetCursorScreenPos(paneMin);
  const std::string id = std::string("slice_") + sliceOrientationName(orientation);
  ImGui::InvisibleButton(
      id.c_str(), ImVec2(std::max(paneMax.x - paneMin.x, 1.f), std::max(paneMax.y - paneMin.y, 1.f)),
      ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
          ImGuiButtonFlags_MouseButtonMiddle);
  noteRect(id);
  pane.drawn = true;
  handleSliceMouse(orientation);
  pane.placement = place();  // with this frame's zoom and pan, so the image follows the gesture
  const SlicePlacement& placed = pane.placement;
  const ImVec2 imageMin = toIm(placed.min), imageMax = toIm(placed.min + placed.size);
  noteRect(id + "_image", imageMin, imageMax);
  draw->PushClipRect(paneMin, paneMax, true);
  draw->AddImage(pane.texture.id(), imageMin, imageMax);
  // The part of the image in view: the overlays stay on it, the letters at its edges.
  const ImVec2 shownMin(std::max(imageMin.x, paneMin.x), std::max(imageMin.y, paneMin.y)),
      shownMax(std::min(imageMax.x, paneMax.x), std::min(imageMax.y, paneMax.y));
  draw->PushClipRect(shownMin, shownMax, true);
  drawSliceCrosshair(orientation);
  if (centerlines)
    for (const SliceCrossing& crossing : sliceCrossings(volume, orientation, cursor, *centerlines))
      draw->AddCircleFilled(toIm(screenOfSlicePixel(placed, crossing.pixel)), 3.5f,
                            IM_COL32(40, 230, 255, 255));
  const SliceLetters letters = sliceLetters(orientation);
  const ImU32 letterColor = IM_COL32(255, 255, 255, 200);
  const float midX = (shownMin.x + shownMax.x) / 2, midY = (shownMin.y + shownMax.y) / 2;
  const auto letter = [&](char c, ImVec2 at) { draw->AddText(at, letterColor, &c, &c + 1); };
  letter(letters.left, ImVec2(shownMin.x + 3, midY - 7));
  letter(letters.right, ImVec2(shownMax.x - 11, midY - 7));
  letter(letters.top, ImVec2(midX - 3, shownMin.y + 2));
  letter(letters.bottom, ImVec2(midX - 3, shownMax.y - 16));
  draw->PopClipRect();
  draw->PopClipRect();
}

// The other two planes through the cursor: a line each, open around the cursor's point.
void App::drawSliceCrosshair(SliceOrientation orientation) {
  const SlicePlacement& placed = slices_.panes[int(orientation)].placement;
  const glm::dvec2 at =
      screenOfSlicePixel(placed, slicePixelOf(data_.volume, orientation, sliceCursor()));
  const SliceAxes axes = axesOf(orientation);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  constexpr float kGap = 8;
  const ImU32 vertical = planeColor(planeOfAxis(axes.x), 170),
              horizontal = planeColor(planeOfAxis(axes.y), 170);
  const float x = float(at.x), y = float(at.y);
  const float left = float(placed.min.x), right = float(placed.min.x + placed.size.x);
  const float top = float(placed.min.y), bottom = float(placed.min.y + placed.size.y);
  draw->AddLine(ImVec2(x, top), ImVec2(x, y - kGap), vertical);
  draw->AddLine(ImVec2(x, y + kGap), ImVec2(x, bottom), vertical);
  draw->AddLine(ImVec2(left, y), ImVec2(x - kGap, y), horizontal);
  draw->AddLine(ImVec2(x + kGap, y), ImVec2(right, y), horizontal);
}

// Right after the slice's button: press or drag with the left button moves the cursor (on the
// image), the right button's drag sets window/level, the wheel steps through slices; Ctrl+wheel
// zooms about the pointer, a middle drag pans, a double click fits again; hovering reads the voxel.
void App::handleSliceMouse(SliceOrientation orientation) {
  const SlicePaneUi& pane = slices_.panes[int(orientation)];
  const ImGuiIO& io = ImGui::GetIO();
  const glm::dvec2 pixel =
      slicePixelOfScreen(pane.placement, {double(io.MousePos.x), double(io.MousePos.y)});
  const bool onImage = glm::all(glm::greaterThanEqual(pixel, glm::dvec2(0.0))) &&
                       glm::all(glm::lessThan(pixel, glm::dvec2(pane.size)));
  const glm::dvec3 cursor = sliceCursor();
  if (ImGui::IsItemHovered() && onImage)
    slices_.hoveredVoxel = cursorVoxel(
        data_.volume,
        clampToVolume(data_.volume, pointOfSlicePixel(data_.volume, orientation, pixel, cursor)));
  if (ImGui::IsItemActive()) slices_.held = true;
  zoomOrPanSlice(orientation);
  if (io.KeyCtrl || ImGui::IsMouseDown(ImGuiMouseButton_Middle)) return;
  if (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left) && onImage) {
    const glm::dvec3 moved =
        clampToVolume(data_.volume, pointOfSlicePixel(data_.volume, orientation, pixel, cursor));
    if (moved != cursor) moveSliceCursor(moved);
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
    if (!slices_.windowLevelAtPress) slices_.windowLevelAtPress = doc().slices.windowLevel;
    const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Right, 0.f);
    SliceViewState slices = doc().slices;
    slices.windowLevel = draggedWindowLevel(*slices_.windowLevelAtPress, {drag.x, drag.y});
    commit(SliceViewEdit{slices});
  }
  if (ImGui::IsItemHovered() && io.MouseWheel != 0) {
    const int steps = (io.MouseWheel > 0 ? 1 : -1) * (io.KeyShift ? 10 : 1) *
                      std::max(int(std::lround(std::abs(io.MouseWheel))), 1);
    moveSliceCursor(steppedCursor(data_.volume, orientation, cursor, steps));
  }
}

// The pane's view gestures (handleSliceMouse).
void App::zoomOrPanSlice(SliceOrientation orientation) {
  const SlicePlacement& placed = slices_.panes[int(orientation)].placement;
  const ImGuiIO& io = ImGui::GetIO();
  SliceViewState slices = doc().slices;
  SlicePaneView& view = slices.panes[int(orientation)];
  // The fitted image's centre on the screen: the placement's centre less the pan.
  const glm::dvec2 home = placed.min + placed.size * 0.5 - view.panPx;
  if (ImGui::IsItemHovered() && io.KeyCtrl && io.MouseWheel != 0)
    zoomAboutPointer(view.zoom, view.panPx, glm::dvec2(io.MousePos.x, io.MousePos.y) - home,
                     io.MouseWheel, kMinSliceZoom, kMaxSliceZoom);
  if (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Middle) && !ImGui::IsItemActivated())
    view.panPx += glm::dvec2(io.MouseDelta.x, io.MouseDelta.y);
  if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) view = {};
  if (!(slices == doc().slices)) commit(SliceViewEdit{slices});
}

// The column beside the image: a caption with the voxel under the mouse, then the three slices.
void App::drawSliceView() {
  slices_.held = false;
  slices_.hoveredVoxel.reset();
  for (SlicePaneUi& pane : slices_.panes) pane.drawn = false;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Right)) slices_.windowLevelAtPress.reset();
  const float width = sliceViewWidth();
  if (width <= 0) return;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(
      ImVec2(std::max(io.DisplaySize.x - kPanelWidth - cprViewWidth() - width, 64.f), 0));
  ImGui::SetNextWindowSize(ImVec2(width, std::max(io.DisplaySize.y - kStatusHeight, 64.f)));
  ImGui::Begin("##slices", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
  const ImVec2 caption = ImGui::GetCursorScreenPos();
  ImGui::NewLine();
  const Centerlines* centerlines = nullptr;
  try {
    centerlines = framedCenterlines();
  } catch (const std::exception&) {  // the VesselGlyph section says why
  }
  const ImVec2 at = ImGui::GetCursorScreenPos(), avail = ImGui::GetContentRegionAvail();
  const float paneHeight = std::floor(avail.y / 3);
  for (const SliceOrientation orientation : kOrientations)
    drawSlicePane(orientation, ImVec2(at.x, at.y + paneHeight * float(orientation)),
                  ImVec2(avail.x, paneHeight - 4), centerlines);
  char text[128];
  const WindowLevel wl = doc().slices.windowLevel;
  if (slices_.hoveredVoxel) {
    const glm::ivec3 v = *slices_.hoveredVoxel;
    std::snprintf(text, sizeof text, "%d %d %d  %.0f HU   W %.0f L %.0f", v.x, v.y, v.z,
                  huOfDensity(data_.volume.densityAt(v.x, v.y, v.z)), wl.window, wl.level);
  } else {
    std::snprintf(text, sizeof text, "W %.0f L %.0f   right-drag: W/L", wl.window, wl.level);
  }
  ImGui::GetWindowDrawList()->AddText(caption, IM_COL32(200, 200, 200, 255), text);
  ImGui::End();
}

nlohmann::json App::slicesReport() const {
  const glm::dvec3 cursor = sliceCursor();
  const glm::ivec3 voxel = cursorVoxel(data_.volume, cursor);
  nlohmann::json panes = nlohmann::json::object();
  for (const SliceOrientation orientation : kOrientations) {
    const SlicePaneUi& pane = slices_.panes[int(orientation)];
    if (!pane.drawn || !pane.shown) continue;
    panes[sliceOrientationName(orientation)] = {
        {"index", pane.shown->index}, {"width", pane.size.x}, {"height", pane.size.y}};
  }
  nlohmann::json hovered = nullptr;
  if (slices_.hoveredVoxel)
    hovered = {slices_.hoveredVoxel->x, slices_.hoveredVoxel->y, slices_.hoveredVoxel->z};
  return {{"shown", sliceViewWidth() > 0},
          {"cursor_mm", {cursor.x, cursor.y, cursor.z}},
          {"cursor_voxel", {voxel.x, voxel.y, voxel.z}},
          {"hu", huOfDensity(data_.volume.densityAt(voxel.x, voxel.y, voxel.z))},
          {"hovered_voxel", hovered},
          {"panes", panes}};
}

}  // namespace angio
