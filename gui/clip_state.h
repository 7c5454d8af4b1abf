#pragma once
// The Crop & clip section's settings as the user set them (gui/panel_clip.h) and the view
// clipping they stand for (core/view_clipping.h). Each part keeps its values while switched off,
// so turning it on again brings them back.
#include <glm/glm.hpp>

#include "core/render_params.h"
#include "core/view_clipping.h"

namespace angio {

struct ClipState {
  bool cropOn = false;
  CropBox crop;  // mm of the volume frame; the whole domain when first turned on (empty: unset)
  bool planeOn = false;
  bool facingViewer = true;  // else the normal is +-normalAxis
  Axis normalAxis = Axis::i;
  bool flipNormal = false;   // the normal along -normalAxis
  double planeOffsetMm = 0;  // facing: depth from the centre; else along the normal from it
  bool slabOn = false;
  ThickSlab slab{0, 20};

  friend bool operator==(const ClipState&, const ClipState&) = default;
};

// The clipping to render with, for a volume whose domain extent is `extentMm` (the plane's
// point is the domain centre moved along its normal).
ViewClipping viewClippingOf(const ClipState& clip, glm::dvec3 extentMm);

// The plane's unit normal when it does not face the viewer.
glm::dvec3 clipNormalOf(const ClipState& clip);

}  // namespace angio
