#pragma once
// Zooming an image about the pointer, shared by the 3-D view and the CPR pane: the image point
// under the pointer stays under it.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace angio {

// `fromHome` is the pointer's offset from the image's unpanned centre (screen pixels); the wheel
// zooms 1.2x per notch, within [minZoom, maxZoom].
inline void zoomAboutPointer(double& zoom, glm::dvec2& panPx, glm::dvec2 fromHome, double wheel,
                             double minZoom, double maxZoom) {
  const double newZoom = std::clamp(zoom * std::pow(1.2, wheel), minZoom, maxZoom);
  const glm::dvec2 fromCentre = fromHome - panPx;
  panPx += fromCentre - fromCentre * (newZoom / zoom);
  zoom = newZoom;
}

}  // namespace angio
