#include "phantom/phantom_geometry.h"

#include <algorithm>
#include <cmath>

namespace angio::phantom {

double signedDistance(const Capsule& shape, glm::dvec3 p) {
  const glm::dvec3 ab = shape.b - shape.a;
  const double length2 = glm::dot(ab, ab);
  const double t = length2 > 0 ? std::clamp(glm::dot(p - shape.a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (shape.a + t * ab)) - glm::mix(shape.ra, shape.rb, t);
}

double signedDistance(const Ellipsoid& shape, glm::dvec3 p) {
  const glm::dvec3 local = glm::transpose(shape.axes) * (p - shape.centre);
  const double q = glm::length(local / shape.radii);
  const double gradient = glm::length(local / (shape.radii * shape.radii));
  const double deepest = -std::min({shape.radii.x, shape.radii.y, shape.radii.z});
  if (gradient * q < 1e-12) return deepest;
  // f = |q| - 1 has |grad f| = |local / r^2| / |q|.
  return std::max((q - 1.0) * q / gradient, deepest);
}

double ellipseSignedDistance(glm::dvec2 d, glm::dvec2 radii) {
  const double q = glm::length(d / radii);
  const double gradient = glm::length(d / (radii * radii));
  const double deepest = -std::min(radii.x, radii.y);
  if (gradient * q < 1e-12) return deepest;
  return std::max((q - 1.0) * q / gradient, deepest);
}

double signedDistance(const EllipticCylinder& shape, glm::dvec3 p) {
  // Distance to the shape shrunk by the rounding radius, minus that radius: rounded edges.
  const double round = shape.roundingMm;
  const glm::dvec3 d = p - shape.centre;
  const double side = ellipseSignedDistance(glm::dvec2(d), shape.radii - round);
  const double cap = std::abs(d.z) - (shape.halfHeight - round);
  const double outside = std::hypot(std::max(side, 0.0), std::max(cap, 0.0));
  return outside + std::min(std::max(side, cap), 0.0) - round;
}

Bounds boundsOf(const Capsule& shape) {
  Bounds bounds;
  bounds.add(shape.a - shape.ra);
  bounds.add(shape.a + shape.ra);
  bounds.add(shape.b - shape.rb);
  bounds.add(shape.b + shape.rb);
  return bounds;
}

Bounds boundsOf(const Ellipsoid& shape) {
  // Half-extent along world axis w: |sum over ellipsoid axes of axis_w * radius|, Euclidean.
  glm::dvec3 half(0.0);
  for (int w = 0; w < 3; ++w) {
    double sum = 0;
    for (int a = 0; a < 3; ++a) sum += std::pow(shape.axes[a][w] * shape.radii[a], 2);
    half[w] = std::sqrt(sum);
  }
  return {shape.centre - half, shape.centre + half};
}

Bounds boundsOf(const EllipticCylinder& shape) {
  const glm::dvec3 half(shape.radii, shape.halfHeight);
  return {shape.centre - half, shape.centre + half};
}

Ellipsoid uprightPlate(glm::dvec3 centre, glm::dvec2 along, glm::dvec3 radii) {
  const glm::dvec3 u(glm::normalize(along), 0.0);
  const glm::dvec3 v(0.0, 0.0, 1.0);
  return {centre, glm::dmat3(u, v, glm::cross(u, v)), radii};
}

namespace {

// Barry-Goldman pyramid for one span p1..p2 of a centripetal Catmull-Rom spline.
glm::dvec3 catmullRomPoint(const glm::dvec3 p[4], double u) {
  double t[4] = {0, 0, 0, 0};
  for (int n = 1; n < 4; ++n) {
    t[n] = t[n - 1] + std::max(std::sqrt(glm::length(p[n] - p[n - 1])), 1e-6);
  }
  const double s = glm::mix(t[1], t[2], u);
  auto lerp = [&](glm::dvec3 a, glm::dvec3 b, double ta, double tb) {
    return ((tb - s) * a + (s - ta) * b) / (tb - ta);
  };
  const glm::dvec3 a1 = lerp(p[0], p[1], t[0], t[1]);
  const glm::dvec3 a2 = lerp(p[1], p[2], t[1], t[2]);
  const glm::dvec3 a3 = lerp(p[2], p[3], t[2], t[3]);
  const glm::dvec3 b1 = lerp(a1, a2, t[0], t[2]);
  const glm::dvec3 b2 = lerp(a2, a3, t[1], t[3]);
  return lerp(b1, b2, t[1], t[2]);
}

}  // namespace

std::vector<CurvePoint> catmullRom(const std::vector<CurvePoint>& knots, int samplesPerSpan) {
  const int n = int(knots.size());
  if (n < 2) return knots;
  // Phantom end knots mirror their neighbours, so the curve leaves the ends straight.
  auto knot = [&](int index) {
    if (index < 0) return 2.0 * knots[0].position - knots[1].position;
    if (index >= n) return 2.0 * knots[n - 1].position - knots[n - 2].position;
    return knots[index].position;
  };
  std::vector<CurvePoint> curve;
  for (int span = 0; span + 1 < n; ++span) {
    const glm::dvec3 p[4] = {knot(span - 1), knot(span), knot(span + 1), knot(span + 2)};
    for (int s = 0; s < samplesPerSpan; ++s) {
      const double u = double(s) / samplesPerSpan;
      curve.push_back({catmullRomPoint(p, u), glm::mix(knots[span].radius, knots[span + 1].radius, u)});
    }
  }
  curve.push_back(knots.back());
  return curve;
}

std::vector<double> arcLengths(const std::vector<CurvePoint>& curve) {
  std::vector<double> lengths(curve.size(), 0.0);
  for (std::size_t n = 1; n < curve.size(); ++n) {
    lengths[n] = lengths[n - 1] + glm::length(curve[n].position - curve[n - 1].position);
  }
  return lengths;
}

std::vector<CurvePoint> resample(const std::vector<CurvePoint>& curve, double stepMm) {
  if (curve.size() < 2) return curve;
  const std::vector<double> lengths = arcLengths(curve);
  const double total = lengths.back();
  const int steps = std::max(1, int(std::ceil(total / stepMm)));
  std::vector<CurvePoint> out;
  out.reserve(steps + 1);
  std::size_t segment = 0;
  for (int n = 0; n <= steps; ++n) {
    const double s = total * n / steps;
    while (segment + 2 < curve.size() && lengths[segment + 1] < s) ++segment;
    const double span = lengths[segment + 1] - lengths[segment];
    const double u = span > 0 ? std::clamp((s - lengths[segment]) / span, 0.0, 1.0) : 0.0;
    out.push_back({glm::mix(curve[segment].position, curve[segment + 1].position, u),
                   glm::mix(curve[segment].radius, curve[segment + 1].radius, u)});
  }
  return out;
}

glm::dvec3 perpendicular(glm::dvec3 t) {
  const glm::dvec3 helper = std::abs(t.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  return glm::normalize(glm::cross(t, helper));
}

}  // namespace angio::phantom
