#include "gui/cpr_pane.h"

#include <algorithm>
#include <cmath>

namespace angio {

CprPlacement placeCpr(glm::ivec2 imageSize, glm::dvec2 paneMin, glm::dvec2 paneSize, double zoom,
                      glm::dvec2 panPx) {
  const glm::dvec2 image = glm::max(glm::dvec2(imageSize), glm::dvec2(1.0));
  const double fit = std::max(std::min(paneSize.x / image.x, paneSize.y / image.y), 1e-3);
  CprPlacement placement;
  placement.scale = fit * zoom;
  placement.home = {paneMin.x + paneSize.x / 2, paneMin.y + image.y * fit / 2};
  placement.min = placement.home + panPx - image * placement.scale / 2.0;
  return placement;
}

glm::dvec2 screenOfCprPixel(const CprPlacement& placement, glm::dvec2 pixel) {
  return placement.min + (pixel + 0.5) * placement.scale;
}

glm::ivec2 cprPixelUnder(const CprPlacement& placement, glm::dvec2 screen) {
  const glm::dvec2 pixel = glm::floor((screen - placement.min) / placement.scale);
  return {int(std::clamp(pixel.x, -1e9, 1e9)), int(std::clamp(pixel.y, -1e9, 1e9))};
}

double rulerStepMm(double pixelsPerMm) {
  for (double step : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0})
    if (step * pixelsPerMm >= kMinTickGapPx) return step;
  return 100;
}

}  // namespace angio
