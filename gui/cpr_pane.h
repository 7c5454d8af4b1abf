#pragma once
// The CPR pane's geometry as a reading view: where the CPR image sits at the pane's zoom and pan
// (fitted, top-centred at zoom 1), the mapping between screen and CPR pixels, and the ruler's tick
// spacing for the zoom. Pure functions of plain values, so they are tested without a window.
#include <glm/glm.hpp>

namespace angio {

constexpr double kMinCprZoom = 0.25, kMaxCprZoom = 32;

// Screen = min + (pixel + 0.5) * scale for CPR pixel coordinates (centres at integers).
struct CprPlacement {
  glm::dvec2 min{0.0};   // screen position of the image's top-left corner
  double scale = 1;      // screen pixels per CPR pixel
  glm::dvec2 home{0.0};  // the image centre at zoom 1 without pan (what the wheel zooms about)

  friend bool operator==(const CprPlacement&, const CprPlacement&) = default;
};

// At zoom 1 the whole image fits the pane, centred across and at the pane's top; zoom scales it
// about that centre, pan (screen pixels) moves it.
CprPlacement placeCpr(glm::ivec2 imageSize, glm::dvec2 paneMin, glm::dvec2 paneSize, double zoom,
                      glm::dvec2 panPx);
glm::dvec2 screenOfCprPixel(const CprPlacement& placement, glm::dvec2 pixel);
glm::ivec2 cprPixelUnder(const CprPlacement& placement, glm::dvec2 screen);

// The ruler's tick spacing (mm) at `pixelsPerMm` on the screen: the finest of 1, 2, 5, 10, 20, 50,
// 100 mm whose ticks stay kMinTickGapPx apart.
constexpr double kMinTickGapPx = 6;
double rulerStepMm(double pixelsPerMm);

}  // namespace angio
