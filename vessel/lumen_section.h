#pragma once
// The lumen's cross-section through a point, perpendicular to the vessel: rays in that plane from
// the point find the wall where the density falls (or, at calcium, rises) to half way between the
// lumen and what lies beyond it (full width at half maximum, so partial volume at the wall counts
// as the scanner's blur, not as lumen or wall). The wall points give the section's centre (the
// centroid of their polygon) and its radius (that of the circle of equal area). Sub-voxel, and
// what places traced centerlines on the lumen's centre and gives them their radii.
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/volume.h"
#include "vessel/centerline.h"
#include "vessel/lumen_field.h"

namespace angio {

struct LumenSection {
  glm::dvec3 centreMm{0.0};  // volume frame
  double radiusMm = 0;
};

// The section through pointMm (volume frame) perpendicular to `tangent`, searching walls up to
// searchRadiusMm away; the centre found is searched again from itself a few times (it moves
// towards the middle of the lumen). None where fewer than half of the rays meet a wall or the
// point is not inside the range.
std::optional<LumenSection> lumenSection(const Volume& volume, ContrastRange range, glm::dvec3 pointMm,
                                         glm::dvec3 tangent, double searchRadiusMm);

// A voxel path made a centerline: resampled every stepMm along a smoothed copy, each point moved
// to its section's centre with the section's radius (points whose section fails keep their place
// and take their neighbours' radius), then smoothed again lightly. Volume frame. `wallMm` gives a
// first radius guess per voxel (the distance map), which bounds each section's search.
CenterlinePath centerlineFromVoxels(const Volume& volume, ContrastRange range,
                                    const std::vector<glm::ivec3>& voxels,
                                    const std::vector<float>& wallMm, double stepMm);

}  // namespace angio
