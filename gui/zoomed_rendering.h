#pragma once
// What a zoomed view renders: only the part of the image plane the viewport shows (an image
// window, core/render_params.h), with each level's image sampling distance divided by the zoom
// down to one image pixel per screen pixel. A zoomed view then stays as sharp as at zoom 1 and
// costs about as many pixels, instead of magnifying a texture rendered for zoom 1.
#include <optional>

#include <glm/glm.hpp>

#include "core/render_params.h"
#include "gui/document.h"
#include "render/progressive_renderer.h"

namespace angio {

// The viewport's screen geometry: its size in pixels and the size in mm that fits it at zoom 1
// (ViewportOverlay::fitMm).
struct ViewportFit {
  glm::dvec2 sizePx{0.0};
  glm::dvec2 fitMm{1.0};
  friend bool operator==(const ViewportFit&, const ViewportFit&) = default;
};

// Screen pixels per mm of the image plane at `zoom` (what drawViewport draws with).
double viewportPixelsPerMm(const ViewportFit& fit, double zoom);

// The part of the image plane the viewport shows at the view's zoom and pan, widened to a grid of
// 32 screen pixels so that a small pan keeps the window (and the frame) it has; none up to zoom 1,
// where the whole image is in view.
std::optional<ImageWindow> visibleWindow(const ViewState& view, const ViewportFit& fit);

// Each level's isd divided by the zoom, but not finer than a screen pixel (`screenIsd`, voxel
// units) nor coarser than the level's own; unchanged up to zoom 1.
LevelSamplings zoomedLevels(LevelSamplings levels, double zoom, double screenIsd);

}  // namespace angio
