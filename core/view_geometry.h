#pragma once
// View geometry of the rendering model: parallel projection, rotation by theta about voxel axis a,
// image of W x H pixels at distance D = isd * u, samples at t = k * delta on one global grid.
#include <glm/glm.hpp>

#include "core/render_params.h"
#include "core/volume.h"

namespace angio {

struct ViewGeometry {
  int width = 0;          // W = ceil(hypot(E_b, E_c) / D)
  int height = 0;         // H = ceil(E_a / D)
  double pixelMm = 0;     // D
  double sampleMm = 0;    // delta
  glm::dvec3 extent{0};   // E (mm)
  glm::dvec3 centre{0};   // P0 = E / 2 (mm, volume frame)
  glm::dvec3 right{0};    // r
  glm::dvec3 up{0};       // e_a
  glm::dvec3 viewDir{0};  // d
  int axis = 2;           // a, b, c as indices 0..2
  int axisB = 0;
  int axisC = 1;

  // Ray origin (t = 0) of pixel (x, y), in mm of the volume frame.
  glm::dvec3 rayOrigin(int x, int y) const;
};

ViewGeometry makeViewGeometry(const Volume& volume, const RenderParams& params);

// Where a point (volume frame, mm) lies on the image, in pixels: the inverse of rayOrigin for the
// point's ray (pixel x covers [x, x + 1), row 0 at the top).
glm::dvec2 imagePointOf(const ViewGeometry& view, glm::dvec3 pointMm);

// The integer sample range [first, last] of a ray: the k with p(k * delta) inside the closed
// domain box [0, E]. Empty (first > last) when the ray misses the box.
struct SampleRange {
  long first = 1;
  long last = 0;
  bool empty() const { return first > last; }
};
SampleRange sampleRange(const ViewGeometry& view, glm::dvec3 origin);

}  // namespace angio
