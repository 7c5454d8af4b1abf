#pragma once
// The viewport: the rendered image as a texture, aspect-correct, zoomed with the wheel about the
// cursor, panned with the right or middle button, rotated with a left drag; double-click resets
// zoom and pan. Overlays: orientation letters on the image edges, a scale bar in mm, the angle.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <imgui.h>

#include "core/render_params.h"
#include "gui/document.h"
#include "gui/zoomed_rendering.h"

namespace angio {

// The image on screen. Pixels are square in mm: D = isd * u both ways (rendering model).
struct ViewportImage {
  ImTextureID texture = nullptr;
  int width = 0, height = 0;  // pixels
  double pixelMm = 0;         // D
  glm::dvec2 centreMm{0.0};   // the image's centre from P0 (h right, v up): an image window's
};

// What to draw around the image.
struct ViewportOverlay {
  glm::dvec2 fitMm{1.0};   // the size that fits the viewport at zoom 1: (hypot(E_b, E_c), E_a) mm
  std::string caption;     // top-left, e.g. "23.0 deg about k"
  std::string levelLabel;  // top-right, e.g. "high  isd 0.5  osd 0.3  trilinear"
  std::vector<std::string> banner;  // bottom-right: the patient and study (gui/study_banner.h)
};

struct ViewportInteraction {
  double rotateDegrees = 0;  // from a left drag this frame
  // A Shift+left drag's motion this frame (screen pixels): the TF or the MIP window, not a turn.
  glm::vec2 adjustPx{0.f};
  std::optional<ViewState> zoomedOrPanned;  // the view with this frame's zoom and pan, if changed
  bool reset = false;                       // double-click: zoom and pan were reset
  ImVec2 min, max;                          // the viewport's screen rectangle
  bool hasImage = false;                    // an image was drawn, at:
  ImVec2 imageMin, imageMax;                // its screen rectangle (may reach beyond the viewport)
};

// The LPS letter a direction in the volume frame mostly points to (voxel axes i, j, k along +L,
// +P, +S; -x R, -y A, -z I); a tie goes to the earlier axis.
char lpsLetter(const glm::dvec3& direction);

// The letters (L/R/A/P/S/I) of the dominant LPS axis of +r, -r, +up and -up for a view about
// `axis` at `angleDeg` (rendering model, View: r = cos(t) e_b + sin(t) e_c, up = e_a).
struct OrientationLetters {
  char right = '?', left = '?', top = '?', bottom = '?';
};
OrientationLetters orientationLetters(Axis axis, double angleDeg);

// The zoom at which the view at `angleDeg` about `axis` fills a viewport of `sizePx`: the
// domain's projection (E_b |cos t| + E_c |sin t| wide, E_a high) rather than zoom 1's
// rotation-proof fit to hypot(E_b, E_c), so an elongated volume seen across fills the width.
double zoomToFitView(glm::dvec3 extentMm, Axis axis, double angleDeg, glm::dvec2 sizePx);

// A scale bar length (mm) of 1, 2 or 5 times a power of ten, about `targetPx` long on screen.
double scaleBarMm(double pixelsPerMm, double targetPx);

// Draws into the current window's remaining content region; `image` may be null (nothing yet).
// Overlay text with a one-pixel shadow, legible over any image.
void textWithShadow(ImDrawList* draw, ImVec2 at, ImU32 color, const char* text);

ViewportInteraction drawViewport(const ViewportImage* image, const ViewState& view,
                                 const ViewportOverlay& overlay);

}  // namespace angio
