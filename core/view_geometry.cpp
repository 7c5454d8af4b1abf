#include "core/view_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace angio {

namespace {

// Pixels along a side of `extent` pixels, at least 1; past kMaxImageSide it stays there (int cannot
// hold it, and such an image is refused by its size before anything renders it).
constexpr double kMaxImageSide = 1 << 24;
int pixelCount(double extent) { return int(std::clamp(std::ceil(extent), 1.0, kMaxImageSide)); }

glm::dvec3 unitAxis(int index) {
  glm::dvec3 e(0.0);
  e[index] = 1.0;
  return e;
}

// Makes `view` the window's: its pixels, and the centre moved so that rayOrigin(x, y) is the whole
// image's rayOrigin(windowX + x, windowY + y).
void applyWindow(ViewGeometry& view, const ImageWindow& window) {
  const PixelSpan span = windowPixels(window, view.wholeWidth, view.wholeHeight, view.pixelMm);
  view.windowX = span.x0;
  view.windowY = span.y0;
  view.width = span.x1 - span.x0;
  view.height = span.y1 - span.y0;
  const double h = (span.x0 + view.width * 0.5 - view.wholeWidth * 0.5) * view.pixelMm;
  const double v = (view.wholeHeight * 0.5 - span.y0 - view.height * 0.5) * view.pixelMm;
  view.centre += h * view.right + v * view.up;
}

}  // namespace

ViewGeometry makeViewGeometry(const Volume& volume, const RenderParams& params) {
  if (const std::string problem = renderParamsProblem(params); !problem.empty())
    throw std::invalid_argument(problem);
  ViewGeometry view;
  view.axis = int(params.axis);
  view.axisB = (view.axis + 1) % 3;  // (a, b, c) cyclic: (k, i, j), (i, j, k), (j, k, i)
  view.axisC = (view.axis + 2) % 3;
  const double theta = params.angleDeg * M_PI / 180.0;
  const double c = std::cos(theta), s = std::sin(theta);
  view.viewDir = c * unitAxis(view.axisC) - s * unitAxis(view.axisB);
  view.right = c * unitAxis(view.axisB) + s * unitAxis(view.axisC);
  view.up = unitAxis(view.axis);

  const double u = voxelUnit(volume);
  view.pixelMm = params.sampling.isd * u;
  view.sampleMm = params.sampling.osd * u;
  view.extent = domainExtent(volume);
  view.centre = view.extent * 0.5;
  const double diagonal = std::hypot(view.extent[view.axisB], view.extent[view.axisC]);
  view.wholeWidth = view.width = pixelCount(diagonal / view.pixelMm);
  view.wholeHeight = view.height = pixelCount(view.extent[view.axis] / view.pixelMm);
  if (params.window) applyWindow(view, *params.window);
  return view;
}

PixelSpan windowPixels(const ImageWindow& window, int wholeWidth, int wholeHeight, double pixelMm) {
  // Pixel x covers h in [(x - W/2) D, (x + 1 - W/2) D); row y covers v in ((H/2 - y - 1) D, (H/2 - y) D].
  const auto cut = [](double first, double end, int size, int& from, int& to) {
    from = int(std::clamp(std::floor(first), 0.0, size - 1.0));
    to = int(std::clamp(std::ceil(end), from + 1.0, double(size)));
  };
  PixelSpan span;
  cut(window.leftMm / pixelMm + wholeWidth * 0.5, window.rightMm / pixelMm + wholeWidth * 0.5,
      wholeWidth, span.x0, span.x1);
  cut(wholeHeight * 0.5 - window.topMm / pixelMm, wholeHeight * 0.5 - window.bottomMm / pixelMm,
      wholeHeight, span.y0, span.y1);
  return span;
}

glm::dvec3 ViewGeometry::rayOrigin(int x, int y) const {
  const double h = (x + 0.5 - width * 0.5) * pixelMm;
  const double v = (height * 0.5 - y - 0.5) * pixelMm;
  return centre + h * right + v * up;
}

glm::dvec2 imagePointOf(const ViewGeometry& view, glm::dvec3 pointMm) {
  const glm::dvec3 offset = pointMm - view.centre;
  return {glm::dot(offset, view.right) / view.pixelMm + view.width * 0.5,
          view.height * 0.5 - glm::dot(offset, view.up) / view.pixelMm};
}

SampleRange sampleRange(const ViewGeometry& view, glm::dvec3 origin) {
  // Slab test against the closed box [0, E]; a tiny tolerance keeps samples that sit exactly on a
  // face (e.g. theta = 0, where rays run along voxel rows) inside despite rounding.
  constexpr double kEps = 1e-9;
  double tNear = -std::numeric_limits<double>::infinity();
  double tFar = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const double o = origin[axis], d = view.viewDir[axis], e = view.extent[axis];
    if (std::abs(d) < 1e-12) {
      if (o < -kEps || o > e + kEps) return {};
      continue;
    }
    double t0 = (0.0 - o) / d, t1 = (e - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    tNear = std::max(tNear, t0);
    tFar = std::min(tFar, t1);
  }
  if (tNear > tFar + kEps) return {};
  SampleRange range;
  range.first = long(std::ceil(tNear / view.sampleMm - kEps));
  range.last = long(std::floor(tFar / view.sampleMm + kEps));
  return range;
}

}  // namespace angio
