#pragma once
// The linked slice view's runtime state (what the user set is the document's SliceViewState):
// one texture per orientation with the slice it shows, where each was drawn, the gesture under
// way. Drawn by gui/app_slices.cpp.
#include <array>
#include <optional>

#include <imgui.h>

#include "core/window_level.h"
#include "gui/app_gl.h"
#include "gui/slice_pane.h"
#include "render/slice_images.h"

namespace angio {

// What a slice texture shows: a change extracts the slice again.
struct ShownSlice {
  int index = -1;  // the fixed voxel index
  WindowLevel windowLevel;
  friend bool operator==(const ShownSlice&, const ShownSlice&) = default;
};

struct SlicePaneUi {
  explicit SlicePaneUi(const GlApi& gl) : texture(gl) {}
  StreamedTexture texture;
  std::optional<ShownSlice> shown;  // none: nothing uploaded for this dataset yet
  glm::ivec2 size{0};               // the slice image's pixels
  SlicePlacement placement;         // where it was drawn last (screen)
  bool drawn = false;               // ... this frame
};

struct SliceViewPanel {
  explicit SliceViewPanel(const GlApi& gl) : panes{SlicePaneUi(gl), SlicePaneUi(gl), SlicePaneUi(gl)} {}

  std::array<SlicePaneUi, 3> panes;               // axial, coronal, sagittal
  std::optional<WindowLevel> windowLevelAtPress;  // a right-drag's start
  bool held = false;  // a slice is pressed this frame (not an interaction with the 3-D view)
  std::optional<glm::ivec3> hoveredVoxel;  // under the mouse in a slice
};

}  // namespace angio
