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
  bool facingViewer = true;    // else the plane stays put in the volume, across `normal`
  glm::dvec3 normal{1, 0, 0};  // volume frame, unit; the removed side (a voxel axis or oblique)
  double planeOffsetMm = 0;    // facing: depth from the centre; else along the normal from it
  bool slabOn = false;
  ThickSlab slab{0, 20};

  friend bool operator==(const ClipState&, const ClipState&) = default;
};

// The clipping to render with, for a volume whose domain extent is `extentMm` (the plane's
// point is the domain centre moved along its normal).
ViewClipping viewClippingOf(const ClipState& clip, glm::dvec3 extentMm);

// The plane's unit normal when it does not face the viewer (+i for a zero or non-finite one).
glm::dvec3 clipNormalOf(const ClipState& clip);

// The normal from its azimuth in the i-j plane (from +i towards +j) and its elevation towards +k,
// in degrees, and back (azimuth 0 along +-k).
glm::dvec3 normalFromAngles(glm::dvec2 azimuthElevationDeg);
glm::dvec2 anglesOfNormal(glm::dvec3 normal);

// The facing plane fixed where it is: the same cut for the view whose direction towards the
// viewer is `towardsViewer` (volume frame), staying in the volume when the view turns.
ClipState fixedToView(ClipState clip, glm::dvec3 towardsViewer);

// How far the plane can move from the volume centre along `normal` and still cut it: half the
// domain's extent projected on the normal.
double planeReachMm(glm::dvec3 normal, glm::dvec3 extentMm);

}  // namespace angio
