#pragma once
// Render parameters for tests that compare two paths of the fast raycaster image for image: the
// high level's sampling with another filter and sample distance, and one of three variants:
// 0 shaded, 1 unshaded, 2 shaded and clipped by a crop box and a plane tilted towards every axis
// (so the rows of a bundle start at different samples). Each variant at its own angle.
#include <glm/glm.hpp>

#include "core/render_params.h"
#include "core/volume.h"

namespace angio::test_support {

inline RenderParams variedParams(const Volume& volume, Axis axis, Filter filter, double osd,
                                 int variant) {
  RenderParams p;
  p.axis = axis;
  p.angleDeg = 33 + 41 * variant;
  p.sampling = qualitySampling(Quality::high);
  p.sampling.filter = filter;
  p.sampling.osd = osd;
  p.shading.enabled = variant != 1;
  if (variant == 2) {
    const glm::dvec3 extent = domainExtent(volume);
    p.clipping.crop = CropBox{0.12 * extent, 0.83 * extent};
    p.clipping.plane = ClipPlane{false, 0, 0.5 * extent, {0.5, -0.6, 0.7}};
  }
  return p;
}

}  // namespace angio::test_support
