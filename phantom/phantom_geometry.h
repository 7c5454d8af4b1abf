#pragma once
// Geometry of the phantom (core/phantom.cpp): the solid shapes its anatomy is built from, with
// signed distances (mm, negative inside) and bounds, and the smooth curves its vessels follow.
// Distances are exact for spheres, cylinders and equal-radius capsules; for ellipsoids and tapered
// capsules they are first-order estimates, accurate near the surface, which is all the phantom uses
// them for (partial-volume edges and shell thicknesses of a few mm).
#include <glm/glm.hpp>
#include <vector>

namespace angio::phantom {

struct Bounds {
  glm::dvec3 lo{1e300};
  glm::dvec3 hi{-1e300};

  void add(glm::dvec3 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  Bounds grown(double mm) const { return {lo - mm, hi + mm}; }
};

// A cone with spherical caps whose radius goes linearly from ra at a to rb at b.
struct Capsule {
  glm::dvec3 a{0.0};
  glm::dvec3 b{0.0};
  double ra = 0;
  double rb = 0;
};

// axes: columns are the ellipsoid's orthonormal axes; radii along them.
struct Ellipsoid {
  glm::dvec3 centre{0.0};
  glm::dmat3 axes{1.0};
  glm::dvec3 radii{1.0};
};

// A cylinder along z with elliptical cross-section (radii in x, y) and edges rounded by roundingMm.
struct EllipticCylinder {
  glm::dvec3 centre{0.0};
  glm::dvec2 radii{1.0};
  double halfHeight = 1;
  double roundingMm = 0;
};

double signedDistance(const Capsule& shape, glm::dvec3 p);
double signedDistance(const Ellipsoid& shape, glm::dvec3 p);
double signedDistance(const EllipticCylinder& shape, glm::dvec3 p);

// Signed distance to the ellipse |(d.x / radii.x, d.y / radii.y)| = 1 in the plane, d relative to
// its centre (first-order estimate f / |grad f|).
double ellipseSignedDistance(glm::dvec2 d, glm::dvec2 radii);

Bounds boundsOf(const Capsule& shape);
Bounds boundsOf(const Ellipsoid& shape);
Bounds boundsOf(const EllipticCylinder& shape);

// An ellipsoid whose first axis points along `along` (in the xy plane), second along z.
Ellipsoid uprightPlate(glm::dvec3 centre, glm::dvec2 along, glm::dvec3 radii);

// A point of a curve with a radius (mm).
struct CurvePoint {
  glm::dvec3 position{0.0};
  double radius = 0;
};

// Centripetal Catmull-Rom spline through the knots (which it interpolates; centripetal so that it
// neither loops nor overshoots where knots are unevenly spaced), radius interpolated linearly
// between knots; samplesPerSpan points per span.
std::vector<CurvePoint> catmullRom(const std::vector<CurvePoint>& knots, int samplesPerSpan);

// Arc lengths from the first point.
std::vector<double> arcLengths(const std::vector<CurvePoint>& curve);

// The polyline resampled at equal arc-length steps close to stepMm; keeps both end points.
std::vector<CurvePoint> resample(const std::vector<CurvePoint>& curve, double stepMm);

// A unit vector perpendicular to the unit tangent t, continuous for tangents away from +-z.
glm::dvec3 perpendicular(glm::dvec3 t);

}  // namespace angio::phantom
