#pragma once
// Test reference: signed distance (mm, negative inside) from a point to a tapered tube segment
// between centres c0, c1 with radii r0, r1 - the minimum over s of |p - c(s)| - r(s), which is convex
// in s, found by ternary search. Independent of the analytic intersection code under test.
#include <algorithm>

#include <glm/glm.hpp>

namespace angio::test_support {

inline double taperedSegmentSignedDistance(glm::dvec3 c0, double r0, glm::dvec3 c1, double r1,
                                           glm::dvec3 p) {
  const auto f = [&](double s) { return glm::distance(p, glm::mix(c0, c1, s)) - (r0 + s * (r1 - r0)); };
  double lo = 0, hi = 1;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (f(m1) < f(m2)) hi = m2;
    else lo = m1;
  }
  return std::min({f(0), f(1), f((lo + hi) / 2)});
}

}  // namespace angio::test_support
