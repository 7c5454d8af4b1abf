#pragma once
// Ray against a tapered capsule ("round cone"), the building block of the VesselGlyph tube:
// the union of the balls B(c(s), r(s)) for s in [0, 1], centre and radius
// interpolated linearly between two centerline points. That union is the convex hull of the two end
// balls: the two balls plus the frustum of the cone tangent to both, between the tangent circles.
// A tube around a polyline with interpolated radius is the union of its segments' round cones, so
// oblique and horizontal vessels are enclosed as completely as vertical ones (unlike the thesis's
// circles swept inside slices, 5.3.3).
//
// Each ray costs two ball tests and one quadratic (the quadratic formula of thesis 5.3.1, in 3-D).
// Two forms: RoundConeIntersector for rays of any one direction, and DepthRayRoundCone for the
// renderer's rays in view coordinates (h, v, t), where the ray of pixel (h, v) runs along t and
// everything that depends on v alone is computed once per image row.
#include <glm/glm.hpp>

namespace angio {

struct RoundCone {
  glm::dvec3 centre0{0.0};  // mm
  glm::dvec3 centre1{0.0};
  double radius0 = 0;  // mm, >= 0
  double radius1 = 0;
};

// The closed span [begin, end] of ray parameters t (mm along a unit direction); empty when
// begin > end.
struct DepthSpan {
  double begin = 1;
  double end = 0;
  bool empty() const { return begin > end; }
};

// The frustum between the tangent circles, in the cone's frame: z = axial coordinate from centre0
// along `axis`; the surface lies at distance k0 - z tan(alpha) from the axis for zBegin <= z <= zEnd,
// alpha the half-angle (sin alpha = (r0 - r1) / L). Absent when one ball holds the other.
struct TangentFrustum {
  bool present = false;
  glm::dvec3 axis{0.0};
  double k0 = 0, tanAlpha = 0, zBegin = 0, zEnd = 0;

  static TangentFrustum of(const RoundCone& cone);

  // The ray o + t d inside the frustum, from w = o - centre0, wz = w.axis, wd = w.d, ww = w.w,
  // dz = d.axis and quadA = 1 - dz^2 (1 + tan^2 alpha) (per direction).
  DepthSpan span(double wz, double wd, double ww, double dz, double quadA) const;
};

class RoundConeIntersector {
 public:
  // `direction` must have unit length.
  RoundConeIntersector(const RoundCone& cone, glm::dvec3 direction);

  // The t with origin + t direction inside the round cone (boundary included).
  DepthSpan intersect(glm::dvec3 origin) const;

 private:
  RoundCone cone_;
  glm::dvec3 direction_{0.0};
  TangentFrustum frustum_;
  double dz_ = 0, quadA_ = 0;
};

// Rays (h, v, t) along +t, the cone given in view coordinates. `withEndBall` = false leaves out
// the ball at centre1 when the polyline's next segment brings it as its first ball. Per image row
// the piece falls into parts (first ball, end ball, frustum), each meeting the row only within a
// known h-range; a row far from a segment's middle meets its balls alone, which are cheap.
class DepthRayRoundCone {
 public:
  DepthRayRoundCone(const RoundCone& cone, bool withEndBall);

  enum class Part { ball0, ball1, frustum };
  struct RowPart {
    Part part = Part::ball0;
    double hLo = 0, hHi = 0;  // the columns it can cover
  };
  // What depends on the row's v alone.
  struct Row {
    double ball0 = -1, ball1 = -1;  // r^2 - (v - centre_v)^2; < 0: the row misses the ball
    double wz = 0, ww = 0;          // frustum terms at h = centre0's h
    RowPart parts[3];
    int partCount = 0;
  };
  Row row(double v) const;

  // Joins the spans of one part on the rays h = h0 + n dh, n < count, into out[n] (the parts of
  // one piece overlap or touch where a ray meets two of them: the piece is convex).
  void addPartSpans(const Row& row, const RowPart& part, double h0, double dh, int count,
                    DepthSpan* out) const;

  // The whole piece on the ray of pixel (h, row's v): the hull of its parts' spans.
  DepthSpan intersect(const Row& row, double h) const;

 private:
  DepthSpan frustumSpan(const Row& row, double h) const;
  void addFrustumSpansOpeningUp(const Row& row, double h0, double dh, int count, DepthSpan* out) const;

  RoundCone cone_;
  bool withEndBall_ = true;
  TangentFrustum frustum_;
  double quadA_ = 0, invDz_ = 0;
};

}  // namespace angio
