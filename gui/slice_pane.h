#pragma once
// The slice view's geometry and gestures (render/slice_images.h gives the images): where a slice
// image sits in its pane with mm-true proportions, the radiological orientation letters, the
// cursor stepped by the wheel, the window/level a right-drag sets, and the presets readers know.
// Pure functions of plain values, so they are tested without a window.
#include <array>

#include <glm/glm.hpp>

#include "core/volume.h"
#include "core/window_level.h"
#include "render/slice_images.h"

namespace angio {

// A slice image scaled to fit its pane, centred: pixels are spacing-sized (square in mm on the
// screen), so an anisotropic CT is not stretched. Screen = min + pixel * scale.
struct SlicePlacement {
  glm::dvec2 min{0.0};    // screen position of the image's top-left corner
  glm::dvec2 scale{1.0};  // screen pixels per image pixel along x and y
  glm::dvec2 size{0.0};   // screen size of the whole image

  friend bool operator==(const SlicePlacement&, const SlicePlacement&) = default;
};

// At `zoom` about the fitted image's centre, moved by `panPx` (the pane's view, zoom 1 and no
// pan: fitted).
SlicePlacement placeSlice(glm::ivec2 imageSize, glm::dvec2 spacingMm, glm::dvec2 paneMin,
                          glm::dvec2 paneSize, double zoom = 1, glm::dvec2 panPx = glm::dvec2(0.0));
glm::dvec2 screenOfSlicePixel(const SlicePlacement& placement, glm::dvec2 pixel);
glm::dvec2 slicePixelOfScreen(const SlicePlacement& placement, glm::dvec2 screen);

// The patient directions at the image's left, right, top and bottom edges (radiological:
// the patient's right on the image's left; superior up).
struct SliceLetters {
  char left, right, top, bottom;
  friend bool operator==(const SliceLetters&, const SliceLetters&) = default;
};
SliceLetters sliceLetters(SliceOrientation orientation);

// The cursor moved by `steps` voxels along the slice's fixed axis (to the next voxel centre,
// kept inside the volume); the in-plane coordinates stay.
glm::dvec3 steppedCursor(const Volume& volume, SliceOrientation orientation, glm::dvec3 cursorMm,
                         int steps);

// A right-drag's window/level, from the one at the drag's start: right widens the window, down
// raises the level (the image darkens), kHuPerPixel each; the window stays at least 1 HU.
constexpr double kWindowLevelHuPerPixel = 4;
WindowLevel draggedWindowLevel(WindowLevel start, glm::dvec2 dragPx);

struct WindowLevelPreset {
  const char* name;
  WindowLevel windowLevel;
};
// The windows CT readers switch between (window/level, HU): CTA shows contrast lumen bright against
// soft tissue and keeps calcium apart; soft tissue for organs; bone for cortex and marrow; lung
// for air-filled parenchyma.
constexpr std::array<WindowLevelPreset, 4> kWindowLevelPresets{
    {{"CTA", {600, 250}}, {"Soft", {400, 40}}, {"Bone", {2000, 500}}, {"Lung", {1500, -600}}}};

}  // namespace angio
