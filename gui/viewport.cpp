#include "gui/viewport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gui/zoom_pan.h"

namespace angio {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMinZoom = 0.1, kMaxZoom = 64;

// Zoom by the wheel about the cursor: the image point under the cursor stays under it.
void zoomAboutCursor(ViewState& view, ImVec2 centre, ImVec2 mouse, float wheel) {
  zoomAboutPointer(view.zoom, view.panPx, glm::dvec2(mouse.x - centre.x, mouse.y - centre.y), wheel,
                   kMinZoom, kMaxZoom);
}

// Letters at the middle of each edge of the image's visible part, so they stay put on screen
// when the image is zoomed beyond the viewport.
void drawOrientation(ImDrawList* draw, const ViewState& view, ImVec2 imageMin, ImVec2 imageMax,
                     ImVec2 min, ImVec2 max) {
  const OrientationLetters letters = orientationLetters(view.axis, view.angleDeg);
  const ImVec2 visibleMin(std::max(imageMin.x, min.x), std::max(imageMin.y, min.y));
  const ImVec2 visibleMax(std::min(imageMax.x, max.x), std::min(imageMax.y, max.y));
  if (visibleMin.x >= visibleMax.x || visibleMin.y >= visibleMax.y) return;
  const ImVec2 mid((visibleMin.x + visibleMax.x) / 2, (visibleMin.y + visibleMax.y) / 2);
  const ImU32 color = IM_COL32(255, 230, 90, 255);
  const float margin = 6, captionRow = ImGui::GetTextLineHeight() + 8;  // below the captions
  const auto place = [&](char letter, ImVec2 anchor, ImVec2 offset) {
    const char text[2] = {letter, 0};
    const ImVec2 size = ImGui::CalcTextSize(text);
    const ImVec2 at(anchor.x + offset.x * size.x, anchor.y + offset.y * size.y);
    const ImVec2 inside(
        std::clamp(at.x, min.x + margin, std::max(min.x + margin, max.x - size.x - margin)),
        std::clamp(at.y, min.y + captionRow, std::max(min.y + captionRow, max.y - size.y - margin)));
    textWithShadow(draw, inside, color, text);
  };
  place(letters.right, ImVec2(visibleMax.x + 4, mid.y), ImVec2(0, -0.5f));
  place(letters.left, ImVec2(visibleMin.x - 4, mid.y), ImVec2(-1, -0.5f));
  place(letters.top, ImVec2(mid.x, visibleMin.y - 4), ImVec2(-0.5f, -1));
  place(letters.bottom, ImVec2(mid.x, visibleMax.y + 4), ImVec2(-0.5f, 0));
}

void drawScaleBar(ImDrawList* draw, double pixelsPerMm, ImVec2 min, ImVec2 max) {
  const double mm = scaleBarMm(pixelsPerMm, 120);
  const float length = float(mm * pixelsPerMm);
  const ImVec2 start(min.x + 16, max.y - 18);
  const ImU32 color = IM_COL32(240, 240, 240, 255);
  draw->AddRectFilled(ImVec2(start.x - 1, start.y - 5), ImVec2(start.x + length + 1, start.y + 2),
                      IM_COL32(0, 0, 0, 140));
  draw->AddLine(start, ImVec2(start.x + length, start.y), color, 2);
  draw->AddLine(ImVec2(start.x, start.y - 4), ImVec2(start.x, start.y), color, 2);
  draw->AddLine(ImVec2(start.x + length, start.y - 4), ImVec2(start.x + length, start.y), color, 2);
  char label[32];
  std::snprintf(label, sizeof label, mm >= 1 ? "%.0f mm" : "%.2g mm", mm);
  textWithShadow(draw, ImVec2(start.x, start.y - 20), color, label);
}

}  // namespace

char lpsLetter(const glm::dvec3& direction) {
  constexpr char positive[] = {'L', 'P', 'S'}, negative[] = {'R', 'A', 'I'};
  int dominant = 0;
  for (int n = 1; n < 3; ++n)
    if (std::abs(direction[n]) > std::abs(direction[dominant]) + 1e-9) dominant = n;
  return direction[dominant] >= 0 ? positive[dominant] : negative[dominant];
}

OrientationLetters orientationLetters(Axis axis, double angleDeg) {
  const int a = int(axis), b = (a + 1) % 3, c = (a + 2) % 3;  // (a, b, c) cyclic
  const double t = angleDeg * kPi / 180;
  glm::dvec3 right(0.0), up(0.0);
  right[b] = std::cos(t);
  right[c] = std::sin(t);
  up[a] = 1;
  return {lpsLetter(right), lpsLetter(-right), lpsLetter(up), lpsLetter(-up)};
}

double zoomToFitView(glm::dvec3 extentMm, Axis axis, double angleDeg, glm::dvec2 sizePx) {
  const int a = int(axis), b = (a + 1) % 3, c = (a + 2) % 3;
  const double t = angleDeg * std::acos(-1.0) / 180;
  const double across = std::max(std::hypot(extentMm[b], extentMm[c]), 1e-3);
  const double wide =
      std::max(extentMm[b] * std::abs(std::cos(t)) + extentMm[c] * std::abs(std::sin(t)), 1e-3);
  const double high = std::max(extentMm[a], 1e-3);
  const double atZoomOne = std::min(sizePx.x / across, sizePx.y / high);
  return std::min(sizePx.x / wide, sizePx.y / high) / atZoomOne;
}

double scaleBarMm(double pixelsPerMm, double targetPx) {
  const double target = targetPx / std::max(pixelsPerMm, 1e-9);
  const double power = std::pow(10.0, std::floor(std::log10(target)));
  double best = power;
  for (double step : {1.0, 2.0, 5.0, 10.0})
    if (step * power <= target) best = step * power;
  return best;
}

void textWithShadow(ImDrawList* draw, ImVec2 at, ImU32 color, const char* text) {
  draw->AddText(ImVec2(at.x + 1, at.y + 1), IM_COL32(0, 0, 0, 220), text);
  draw->AddText(at, color, text);
}

ViewportInteraction drawViewport(const ViewportImage* image, const ViewState& shownView,
                                 const ViewportOverlay& overlay) {
  ViewportInteraction result;
  ViewState view = shownView;
  const ImVec2 min = ImGui::GetCursorScreenPos();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const ImVec2 size(std::max(avail.x, 16.f), std::max(avail.y, 16.f));
  const ImVec2 max(min.x + size.x, min.y + size.y);
  result.min = min;
  result.max = max;

  ImGui::InvisibleButton("viewport", size,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  const ImGuiIO& io = ImGui::GetIO();
  const ImVec2 centreOfViewport(min.x + size.x / 2, min.y + size.y / 2);
  if (ImGui::IsItemHovered() && io.MouseWheel != 0)
    zoomAboutCursor(view, centreOfViewport, io.MousePos, io.MouseWheel);
  // The press's frame moves nothing: its MouseDelta is the pointer's way to the press point (a
  // jump of hundreds of pixels when a remote desktop warps the pointer and presses in one event
  // batch), not a drag.
  if (ImGui::IsItemActive() && !ImGui::IsItemActivated()) {
    // Grab semantics: dragging right carries the front of the patient to the right.
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left) && io.KeyShift)
      result.adjustPx = {io.MouseDelta.x, io.MouseDelta.y};
    else if (ImGui::IsMouseDown(ImGuiMouseButton_Left))
      result.rotateDegrees = -io.MouseDelta.x * view.degreesPerPixel;
    if (ImGui::IsMouseDown(ImGuiMouseButton_Right) || ImGui::IsMouseDown(ImGuiMouseButton_Middle))
      view.panPx += glm::dvec2(io.MouseDelta.x, io.MouseDelta.y);
  }
  if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    view.zoom = 1;
    view.panPx = glm::dvec2(0.0);
    result.reset = true;
  }

  if (!(view == shownView)) result.zoomedOrPanned = view;

  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(min, max, true);
  draw->AddRectFilled(min, max, IM_COL32(0, 0, 0, 255));
  const double pixelsPerMm = viewportPixelsPerMm({glm::dvec2(size.x, size.y), overlay.fitMm}, view.zoom);
  if (image && image->texture) {
    // The image centre is P0 whatever W and H (rendering model), so every level lines up; an
    // image window's centre is off P0 by its offset.
    const ImVec2 centre(centreOfViewport.x + float(view.panPx.x + image->centreMm.x * pixelsPerMm),
                        centreOfViewport.y + float(view.panPx.y - image->centreMm.y * pixelsPerMm));
    const float halfW = float(image->width * image->pixelMm * pixelsPerMm / 2);
    const float halfH = float(image->height * image->pixelMm * pixelsPerMm / 2);
    const ImVec2 imageMin(centre.x - halfW, centre.y - halfH),
        imageMax(centre.x + halfW, centre.y + halfH);
    draw->AddImage(image->texture, imageMin, imageMax);
    result.hasImage = true;
    result.imageMin = imageMin;
    result.imageMax = imageMax;
    drawOrientation(draw, view, imageMin, imageMax, min, max);
  }
  drawScaleBar(draw, pixelsPerMm, min, max);
  const ImU32 text = IM_COL32(230, 230, 230, 255);
  textWithShadow(draw, ImVec2(min.x + 8, min.y + 6), text, overlay.caption.c_str());
  const ImVec2 labelSize = ImGui::CalcTextSize(overlay.levelLabel.c_str());
  textWithShadow(draw, ImVec2(max.x - labelSize.x - 8, min.y + 6), text, overlay.levelLabel.c_str());
  float bannerY = max.y - 6 - ImGui::GetTextLineHeightWithSpacing() * float(overlay.banner.size());
  for (const std::string& line : overlay.banner) {
    const float width = ImGui::CalcTextSize(line.c_str()).x;
    textWithShadow(draw, ImVec2(max.x - width - 8, bannerY), text, line.c_str());
    bannerY += ImGui::GetTextLineHeightWithSpacing();
  }
  draw->PopClipRect();
  return result;
}

}  // namespace angio
