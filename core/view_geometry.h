#pragma once
// View geometry of the rendering model: parallel projection, rotation by theta about voxel axis a,
// image of W x H pixels at distance D = isd * u, samples at t = k * delta on one global grid.
#include <glm/glm.hpp>

#include "core/render_params.h"
#include "core/volume.h"

namespace angio {

// With an image window (RenderParams::window) the geometry is the window's: width x height pixels
// of the whole W x H image, starting at pixel (windowX, windowY) of it, about a centre moved
// within the image plane by the window's offset. The moved centre keeps the plane through P0
// perpendicular to d as t = 0, so the window's rays are the whole image's rays and sample the same
// depths; everything that works from rayOrigin, imagePointOf, centre, width and height sees a
// smaller image and needs to know nothing of the window.
struct ViewGeometry {
  int width = 0;          // W = ceil(hypot(E_b, E_c) / D); the window's width with a window
  int height = 0;         // H = ceil(E_a / D); likewise
  int windowX = 0;        // the first pixel's column in the whole image (0 without a window)
  int windowY = 0;        // and its row
  int wholeWidth = 0;     // W
  int wholeHeight = 0;    // H
  double pixelMm = 0;     // D
  double sampleMm = 0;    // delta
  glm::dvec3 extent{0};   // E (mm)
  glm::dvec3 centre{0};   // the image's centre: P0 = E / 2 (mm, volume frame), moved by a window
  glm::dvec3 right{0};    // r
  glm::dvec3 up{0};       // e_a
  glm::dvec3 viewDir{0};  // d
  int axis = 2;           // a, b, c as indices 0..2
  int axisB = 0;
  int axisC = 1;

  // Ray origin (t = 0) of pixel (x, y), in mm of the volume frame.
  glm::dvec3 rayOrigin(int x, int y) const;
};

// Throws std::invalid_argument when renderParamsProblem(params) names a problem (a NaN angle or
// sampling distance would make every size below it meaningless).
ViewGeometry makeViewGeometry(const Volume& volume, const RenderParams& params);

// The pixels of a W x H image (pixel size D) that overlap `window`, as [x0, x1) x [y0, y1), cut
// to the image; at least one pixel, so a window beside the image still makes an image.
struct PixelSpan {
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  friend bool operator==(const PixelSpan&, const PixelSpan&) = default;
};
PixelSpan windowPixels(const ImageWindow& window, int wholeWidth, int wholeHeight, double pixelMm);

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
