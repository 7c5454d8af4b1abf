#pragma once
// The 3-D point a click on the rendered image means, found by the rendering model's own ray
// (core/reference_ray.h) through that image point: in DVR where the ray's accumulated opacity
// first reaches a threshold (0.5: the surface the user sees), in MIP the sample with the largest
// density. Shared by bone removal's pick-and-grow and vessel tracing.
#include <optional>

#include <glm/glm.hpp>

#include "core/compositing.h"
#include "core/render_params.h"
#include "core/volume.h"

namespace angio {

struct PickedPoint {
  glm::dvec3 positionMm{0.0};  // volume frame (index * spacing)
  float density = 0;           // the reconstructed density there
};

// `imagePoint` in image pixels of the view's image (pixel x covers [x, x + 1), centre x + 0.5;
// row 0 at the top). Regions are not used (a pick goes through the outside TF and the labels).
// None where the ray misses the volume or never reaches the opacity (DVR).
std::optional<PickedPoint> pickPoint(const Volume& volume, const RegionTables& tables,
                                     const RenderParams& params, glm::dvec2 imagePoint,
                                     double opacity = 0.5);

// The first sample along the same ray whose nearest voxel carries a label (hidden or not): what
// "give back" clicks on when the labelled structure is cut out of the image. None: no label.
std::optional<PickedPoint> pickLabelled(const Volume& volume, const RenderParams& params,
                                        glm::dvec2 imagePoint);

}  // namespace angio
