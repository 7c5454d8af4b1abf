#include "vessel/capsule_intersection.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace angio {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Below this length the two balls are treated as one: the axis is undefined.
constexpr double kMinAxisMm = 1e-9;

DepthSpan hull(DepthSpan a, DepthSpan b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.begin, b.begin), std::max(a.end, b.end)};
}

DepthSpan clip(DepthSpan span, double lo, double hi) {
  return {std::max(span.begin, lo), std::min(span.end, hi)};
}

// The t in `range` where a t^2 + 2 halfB t + c <= 0. The caller guarantees that this set is an
// interval (the frustum is convex), so of the two pieces left by a < 0 at most one is real; the
// hull absorbs a rounding-size second piece.
DepthSpan quadraticNonPositive(double a, double halfB, double c, DepthSpan range) {
  constexpr double kLinear = 1e-12;
  if (std::abs(a) < kLinear) {  // the ray runs parallel to a generator of the cone
    if (halfB == 0) return c <= 0 ? range : DepthSpan{};
    const double root = -c / (2 * halfB);
    return halfB > 0 ? clip(range, -kInfinity, root) : clip(range, root, kInfinity);
  }
  const double discriminant = halfB * halfB - a * c;
  if (discriminant < 0) return a > 0 ? DepthSpan{} : range;  // a < 0: negative everywhere
  // Numerically stable roots (no cancellation between -halfB and the square root).
  const double q = -(halfB + std::copysign(std::sqrt(discriminant), halfB));
  double lo = q / a, hi = q != 0 ? c / q : lo;
  if (lo > hi) std::swap(lo, hi);
  if (a > 0) return clip(range, lo, hi);
  return hull(clip(range, -kInfinity, lo), clip(range, hi, kInfinity));
}

// Ball of radius^2 - (offset across the ray)^2 = `chordSquared` around depth `centre`.
DepthSpan ballChord(double centre, double chordSquared) {
  if (chordSquared < 0) return {};
  const double half = std::sqrt(chordSquared);
  return {centre - half, centre + half};
}

}  // namespace

TangentFrustum TangentFrustum::of(const RoundCone& cone) {
  TangentFrustum frustum;
  const glm::dvec3 along = cone.centre1 - cone.centre0;
  const double length = glm::length(along);
  frustum.present = length > kMinAxisMm && length > std::abs(cone.radius1 - cone.radius0);
  if (!frustum.present) return frustum;
  frustum.axis = along / length;
  // The cone tangent to both balls touches ball n at axial offset r_n sin(alpha) from its centre.
  const double sinAlpha = (cone.radius0 - cone.radius1) / length;
  const double cosAlpha = std::sqrt(1 - sinAlpha * sinAlpha);
  frustum.tanAlpha = sinAlpha / cosAlpha;
  frustum.k0 = cone.radius0 / cosAlpha;
  frustum.zBegin = cone.radius0 * sinAlpha;
  frustum.zEnd = length + cone.radius1 * sinAlpha;
  return frustum;
}

DepthSpan TangentFrustum::span(double wz, double wd, double ww, double dz, double quadA) const {
  // The slab zBegin <= z(t) <= zEnd between the two tangent circles.
  DepthSpan range{-kInfinity, kInfinity};
  if (std::abs(dz) < 1e-12) {
    if (wz < zBegin || wz > zEnd) return {};
  } else {
    range = {(zBegin - wz) / dz, (zEnd - wz) / dz};
    if (range.begin > range.end) std::swap(range.begin, range.end);
  }
  // Inside the cone: |w + t d|^2 - z(t)^2 <= radiusAt(z(t))^2, with radiusAt > 0 in the slab.
  const double m = k0 - tanAlpha * wz;
  const double halfB = wd - wz * dz + m * tanAlpha * dz;
  const double c = ww - wz * wz - m * m;
  return quadraticNonPositive(quadA, halfB, c, range);
}

RoundConeIntersector::RoundConeIntersector(const RoundCone& cone, glm::dvec3 direction)
    : cone_(cone), direction_(direction), frustum_(TangentFrustum::of(cone)) {
  dz_ = glm::dot(direction, frustum_.axis);
  quadA_ = 1 - dz_ * dz_ * (1 + frustum_.tanAlpha * frustum_.tanAlpha);
}

DepthSpan RoundConeIntersector::intersect(glm::dvec3 origin) const {
  const auto ball = [&](glm::dvec3 centre, double radius) {
    const glm::dvec3 w = origin - centre;
    const double b = glm::dot(w, direction_);
    return ballChord(-b, b * b - (glm::dot(w, w) - radius * radius));
  };
  if (!frustum_.present) {
    return cone_.radius0 >= cone_.radius1 ? ball(cone_.centre0, cone_.radius0)
                                          : ball(cone_.centre1, cone_.radius1);
  }
  const glm::dvec3 w = origin - cone_.centre0;
  const DepthSpan frustum =
      frustum_.span(glm::dot(w, frustum_.axis), glm::dot(w, direction_), glm::dot(w, w), dz_, quadA_);
  return hull(hull(ball(cone_.centre0, cone_.radius0), ball(cone_.centre1, cone_.radius1)), frustum);
}

DepthRayRoundCone::DepthRayRoundCone(const RoundCone& cone, bool withEndBall)
    : cone_(cone), withEndBall_(withEndBall), frustum_(TangentFrustum::of(cone)) {
  if (!frustum_.present && cone.radius1 > cone.radius0) {
    // One ball holds the other: keep only the bigger, as ball0.
    std::swap(cone_.centre0, cone_.centre1);
    std::swap(cone_.radius0, cone_.radius1);
  }
  if (!frustum_.present) withEndBall_ = false;
  const double dz = frustum_.axis.z;
  quadA_ = 1 - dz * dz * (1 + frustum_.tanAlpha * frustum_.tanAlpha);
  invDz_ = std::abs(dz) < 1e-12 ? 0.0 : 1 / dz;
}

DepthRayRoundCone::Row DepthRayRoundCone::row(double v) const {
  Row row;
  const double dv0 = v - cone_.centre0.y, dv1 = v - cone_.centre1.y;
  row.ball0 = cone_.radius0 * cone_.radius0 - dv0 * dv0;
  row.ball1 = withEndBall_ ? cone_.radius1 * cone_.radius1 - dv1 * dv1 : -1;
  const auto addBall = [&](Part part, double chordSquared, double h) {
    if (chordSquared < 0) return;
    const double half = std::sqrt(chordSquared);
    row.parts[row.partCount++] = {part, h - half, h + half};
  };
  addBall(Part::ball0, row.ball0, cone_.centre0.x);
  addBall(Part::ball1, row.ball1, cone_.centre1.x);
  if (!frustum_.present) return row;
  // w = (h - c0.h, v - c0.v, -c0.t) at h = c0.h.
  const glm::dvec3& axis = frustum_.axis;
  row.wz = dv0 * axis.y - cone_.centre0.z * axis.z;
  row.ww = dv0 * dv0 + cone_.centre0.z * cone_.centre0.z;
  // The frustum is the union of discs perpendicular to the axis, centre c0 + z axis and radius
  // rho(z) = k0 - z tan(alpha) for z in [zBegin, zEnd]; a disc reaches rho sqrt(1 - axis_v^2)
  // up and down, rho sqrt(1 - axis_h^2) sideways. Those meeting the row form a z-range.
  const double upDown = std::sqrt(std::max(0.0, 1 - axis.y * axis.y));
  const double sideways = std::sqrt(std::max(0.0, 1 - axis.x * axis.x));
  const double k0 = frustum_.k0, tan = frustum_.tanAlpha;
  double zLo = frustum_.zBegin, zHi = frustum_.zEnd;
  const auto requireAtMost = [&](double k, double c) {  // k z <= c
    if (k > 0) {
      zHi = std::min(zHi, c / k);
    } else if (k < 0) {
      zLo = std::max(zLo, c / k);
    } else if (c < 0) {
      zLo = 1, zHi = 0;
    }
  };
  constexpr double kSlack = 1e-9;  // keep grazing rows in: the bounds only limit the work
  requireAtMost(axis.y + tan * upDown, dv0 + k0 * upDown + kSlack);    // disc bottom <= v
  requireAtMost(-axis.y + tan * upDown, -dv0 + k0 * upDown + kSlack);  // disc top >= v
  if (zLo > zHi) return row;
  const auto hExtent = [&](double z, double sign) {
    return cone_.centre0.x + z * axis.x + sign * (k0 - z * tan) * sideways;
  };
  row.parts[row.partCount++] = {Part::frustum, std::min(hExtent(zLo, -1), hExtent(zHi, -1)) - kSlack,
                                std::max(hExtent(zLo, 1), hExtent(zHi, 1)) + kSlack};
  return row;
}

DepthSpan DepthRayRoundCone::frustumSpan(const Row& row, double h) const {
  const double dh0 = h - cone_.centre0.x;
  const double wz = row.wz + dh0 * frustum_.axis.x;
  const double ww = row.ww + dh0 * dh0;
  const double wd = -cone_.centre0.z;
  const double dz = frustum_.axis.z;
  // Common case first: the quadratic opens upwards and the ray misses the infinite cone.
  const double m = frustum_.k0 - frustum_.tanAlpha * wz;
  const double halfB = wd - wz * dz + m * frustum_.tanAlpha * dz;
  const double c = ww - wz * wz - m * m;
  if (quadA_ > 1e-12 && halfB * halfB - quadA_ * c < 0) return {};
  DepthSpan range{-kInfinity, kInfinity};
  if (invDz_ == 0) {
    if (wz < frustum_.zBegin || wz > frustum_.zEnd) return {};
  } else {
    range = {(frustum_.zBegin - wz) * invDz_, (frustum_.zEnd - wz) * invDz_};
    if (range.begin > range.end) std::swap(range.begin, range.end);
  }
  return quadraticNonPositive(quadA_, halfB, c, range);
}

// frustumSpan for many columns when the quadratic opens upwards (the ray is not within the cone's
// half-angle of its axis, by far the common case), with the terms that depend on the column
// alone written out: halfB = hb0 - hb1 wz and c = ww - k0^2 + wz (2 k0 tan - sec^2 wz).
void DepthRayRoundCone::addFrustumSpansOpeningUp(const Row& row, double h0, double dh, int count,
                                                 DepthSpan* out) const {
  const double axisH = frustum_.axis.x, dz = frustum_.axis.z, tan = frustum_.tanAlpha;
  const double k0 = frustum_.k0, secSquared = 1 + tan * tan;
  const double hb0 = -cone_.centre0.z + k0 * tan * dz, hb1 = dz * secSquared;
  const double twoK0Tan = 2 * k0 * tan, k0Squared = k0 * k0, invA = 1 / quadA_;
  if (invDz_ != 0) {
    // The common case, in chunks of columns computed without branches so that the compiler
    // makes vector code of it (vessel/CMakeLists.txt), then joined; the same arithmetic as below.
    constexpr int kChunk = 64;
    for (int first = 0; first < count; first += kChunk) {
      const int chunk = std::min(kChunk, count - first);
      double los[kChunk], his[kChunk];
      for (int k = 0; k < chunk; ++k) {
        const double dh0 = h0 + (first + k) * dh - cone_.centre0.x;
        const double wz = row.wz + dh0 * axisH;
        const double ww = row.ww + dh0 * dh0;
        const double halfB = hb0 - hb1 * wz;
        const double c = ww - k0Squared + wz * (twoK0Tan - secSquared * wz);
        const double discriminant = halfB * halfB - quadA_ * c;
        const double q = -(halfB + std::copysign(std::sqrt(std::max(discriminant, 0.0)), halfB));
        const double quotient = c / (q != 0 ? q : 1.0);
        const double root0 = q * invA, root1 = q != 0 ? quotient : root0;
        const double z0 = (frustum_.zBegin - wz) * invDz_, z1 = (frustum_.zEnd - wz) * invDz_;
        los[k] = discriminant < 0 ? kInfinity : std::max(std::min(root0, root1), std::min(z0, z1));
        his[k] = std::min(std::max(root0, root1), std::max(z0, z1));
      }
      for (int k = 0; k < chunk; ++k) {
        if (los[k] <= his[k]) out[first + k] = hull(out[first + k], {los[k], his[k]});
      }
    }
    return;
  }
  for (int n = 0; n < count; ++n) {
    const double dh0 = h0 + n * dh - cone_.centre0.x;
    const double wz = row.wz + dh0 * axisH;
    const double ww = row.ww + dh0 * dh0;
    const double halfB = hb0 - hb1 * wz;
    const double c = ww - k0Squared + wz * (twoK0Tan - secSquared * wz);
    const double discriminant = halfB * halfB - quadA_ * c;
    if (discriminant < 0) continue;
    const double q = -(halfB + std::copysign(std::sqrt(discriminant), halfB));
    double lo = q * invA, hi = q != 0 ? c / q : lo;
    if (lo > hi) std::swap(lo, hi);
    if (invDz_ != 0) {
      double zLo = (frustum_.zBegin - wz) * invDz_, zHi = (frustum_.zEnd - wz) * invDz_;
      if (zLo > zHi) std::swap(zLo, zHi);
      lo = std::max(lo, zLo);
      hi = std::min(hi, zHi);
    } else if (wz < frustum_.zBegin || wz > frustum_.zEnd) {
      continue;
    }
    if (lo <= hi) out[n] = hull(out[n], {lo, hi});
  }
}

void DepthRayRoundCone::addPartSpans(const Row& row, const RowPart& part, double h0, double dh,
                                     int count, DepthSpan* out) const {
  switch (part.part) {
    case Part::ball0:
    case Part::ball1: {
      const bool first = part.part == Part::ball0;
      const glm::dvec3& centre = first ? cone_.centre0 : cone_.centre1;
      const double chordSquared = first ? row.ball0 : row.ball1;
      for (int n = 0; n < count; ++n) {
        const double offset = h0 + n * dh - centre.x;
        out[n] = hull(out[n], ballChord(centre.z, chordSquared - offset * offset));
      }
      return;
    }
    case Part::frustum:
      if (quadA_ > 1e-6) {
        addFrustumSpansOpeningUp(row, h0, dh, count, out);
      } else {
        for (int n = 0; n < count; ++n) out[n] = hull(out[n], frustumSpan(row, h0 + n * dh));
      }
      return;
  }
}

DepthSpan DepthRayRoundCone::intersect(const Row& row, double h) const {
  DepthSpan span;
  for (int n = 0; n < row.partCount; ++n) addPartSpans(row, row.parts[n], h, 0, 1, &span);
  return span;
}

}  // namespace angio
