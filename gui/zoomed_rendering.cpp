#include "gui/zoomed_rendering.h"

#include <algorithm>
#include <cmath>

namespace angio {

namespace {

constexpr double kFitMargin = 0.95;  // room for the orientation letters at zoom 1
constexpr double kWindowGridPx = 32;

}  // namespace

double viewportPixelsPerMm(const ViewportFit& fit, double zoom) {
  return std::min(fit.sizePx.x / fit.fitMm.x, fit.sizePx.y / fit.fitMm.y) * kFitMargin * zoom;
}

std::optional<ImageWindow> visibleWindow(const ViewState& view, const ViewportFit& fit) {
  if (!(view.zoom > 1) || fit.sizePx.x <= 0 || fit.sizePx.y <= 0) return std::nullopt;
  const double perMm = viewportPixelsPerMm(fit, view.zoom);
  // The image centre (P0) sits at the viewport centre plus the pan; screen y grows downwards.
  const double left = (-fit.sizePx.x / 2 - view.panPx.x) / perMm;
  const double right = (fit.sizePx.x / 2 - view.panPx.x) / perMm;
  const double bottom = (-fit.sizePx.y / 2 + view.panPx.y) / perMm;
  const double top = (fit.sizePx.y / 2 + view.panPx.y) / perMm;
  const double step = kWindowGridPx / perMm;
  return ImageWindow{std::floor(left / step) * step, std::ceil(right / step) * step,
                     std::floor(bottom / step) * step, std::ceil(top / step) * step};
}

LevelSamplings zoomedLevels(LevelSamplings levels, double zoom, double screenIsd) {
  if (!(zoom > 1)) return levels;
  for (Sampling& level : levels) level.isd = std::min(level.isd, std::max(level.isd / zoom, screenIsd));
  return levels;
}

}  // namespace angio
