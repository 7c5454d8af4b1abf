// VesselGlyph ray intervals: the focus tube and the slab context checked against brute force
// (points sampled along every ray, judged by their distance to the centerline), closed forms for
// straight vessels, the cleft and half-vessel options, shared trunks, simplification and
// determinism.
#include "vessel/vessel_glyph.h"

#include <gtest/gtest.h>

#include "tests/vessel/tube_distance.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

#include <tbb/task_arena.h>

#include "core/render_params.h"
#include "core/view_geometry.h"
#include "vessel/capsule_intersection.h"

namespace angio {
namespace {

// Anisotropic on purpose: E = (63, 63, 78.75) mm, u = 1 mm, so medium quality has D = 1 mm and
// the image is 90 x 79.
Volume testVolume() { return makeVolume({64, 64, 64}, {1.0, 1.0, 1.25}); }

ViewGeometry viewAt(const Volume& volume, double angleDeg) {
  RenderParams params;
  params.angleDeg = angleDeg;
  params.sampling = qualitySampling(Quality::medium);
  return makeViewGeometry(volume, params);
}

CenterlinePath sampledPath(const std::string& name, const std::function<glm::dvec3(double)>& curve,
                           int points, double radiusFrom, double radiusTo) {
  CenterlinePath path{name, {}};
  for (int n = 0; n < points; ++n) {
    const double s = double(n) / (points - 1);
    path.points.push_back({curve(s), radiusFrom + s * (radiusTo - radiusFrom)});
  }
  return path;
}

CenterlinePath straightPath(const std::string& name, glm::dvec3 from, glm::dvec3 to, int points,
                            double radius) {
  return sampledPath(
      name, [&](double s) { return glm::mix(from, to, s); }, points, radius, radius);
}

// Oblique and tortuous: corner to corner with wiggles in all three axes, radius 4.5 -> 2 mm.
CenterlinePath tortuousPath() {
  return sampledPath(
      "tortuous",
      [](double s) {
        const double w = 2 * std::numbers::pi * s;
        return glm::dvec3(12 + 38 * s + 6 * std::sin(3 * w), 14 + 34 * s + 5 * std::cos(2 * w),
                          10 + 58 * s + 4 * std::sin(5 * w));
      },
      140, 4.5, 2.0);
}

Centerlines inVolumeFrame(std::vector<CenterlinePath> paths) {
  Centerlines centerlines;
  centerlines.source = "test";
  centerlines.frame = CenterlineFrame::volume;
  centerlines.paths = std::move(paths);
  return centerlines;
}

// Focus = the vessel radius exactly, no context, no simplification: the tube of the centerlines.
VesselGlyphSettings exactFocusOnly() {
  VesselGlyphSettings settings;
  settings.focus = {RadiusMode::vesselFactor, 1.0, 0.0};
  settings.context = ContextShape::none;
  settings.simplifyToleranceMm = 0;
  return settings;
}

// exactFocusOnly() with `slab` as the context.
VesselGlyphSettings exactFocusInSlab(SlabContext slab) {
  VesselGlyphSettings settings = exactFocusOnly();
  settings.context = ContextShape::slab;
  settings.slab = slab;
  return settings;
}

// exactFocusOnly(), simplified with `toleranceMm`.
VesselGlyphSettings simplifiedFocusOnly(double toleranceMm) {
  VesselGlyphSettings settings = exactFocusOnly();
  settings.simplifyToleranceMm = toleranceMm;
  return settings;
}

// Simplified collinear points keep one segment per piece of 256 points, the piece ends kept: one
// chain of (points - 1) / 255 + 2 points.
void expectOneSegmentPerPiece(const GlyphTubes& tubes, std::size_t points) {
  ASSERT_EQ(tubes.chains.size(), 1u);
  EXPECT_EQ(tubes.chains[0].size(), (points - 1) / 255 + 2);
}

struct Pixel {
  int x, y;
};

std::vector<RegionInterval> intervalsOf(const RayRegions& regions, Pixel pixel) {
  const std::size_t n = std::size_t(pixel.y) * regions.width + pixel.x;
  return {regions.intervals.begin() + regions.rayBegin[n],
          regions.intervals.begin() + regions.rayBegin[n + 1]};
}

Region regionAt(const std::vector<RegionInterval>& intervals, double t) {
  for (const RegionInterval& interval : intervals) {
    if (interval.begin <= t && t < interval.end) return interval.region;
  }
  return Region::outside;
}

std::vector<RegionInterval> ofRegion(const std::vector<RegionInterval>& intervals, Region region) {
  std::vector<RegionInterval> found;
  for (const RegionInterval& interval : intervals) {
    if (interval.region == region) found.push_back(interval);
  }
  return found;
}

// Image-space position (h, v) of a volume-frame point, and of a pixel's centre.
glm::dvec2 imagePosition(const ViewGeometry& view, glm::dvec3 pointMm) {
  const glm::dvec3 p = pointMm - view.centre;
  return {glm::dot(p, view.right), glm::dot(p, view.up)};
}

glm::dvec2 pixelPosition(const ViewGeometry& view, Pixel pixel) {
  return {(pixel.x + 0.5 - view.width * 0.5) * view.pixelMm,
          (view.height * 0.5 - pixel.y - 0.5) * view.pixelMm};
}

void expectWellFormed(const RayRegions& regions, const ViewGeometry& view) {
  ASSERT_EQ(regions.width, view.width);
  ASSERT_EQ(regions.height, view.height);
  ASSERT_EQ(regions.rayBegin.size(), std::size_t(view.width) * view.height + 1);
  ASSERT_EQ(regions.rayBegin.front(), 0u);
  ASSERT_EQ(regions.rayBegin.back(), regions.intervals.size());
  for (std::size_t n = 0; n + 1 < regions.rayBegin.size(); ++n) {
    ASSERT_LE(regions.rayBegin[n], regions.rayBegin[n + 1]);
    for (std::uint32_t k = regions.rayBegin[n]; k < regions.rayBegin[n + 1]; ++k) {
      const RegionInterval& interval = regions.intervals[k];
      ASSERT_LT(interval.begin, interval.end) << "pixel " << n;
      ASSERT_NE(interval.region, Region::outside);
      if (k > regions.rayBegin[n]) {
        const RegionInterval& previous = regions.intervals[k - 1];
        ASSERT_LE(previous.end, interval.begin) << "pixel " << n << ": overlap or unsorted";
        if (previous.end == interval.begin) {
          ASSERT_NE(previous.region, interval.region) << "pixel " << n << ": not merged";
        }
      }
    }
  }
}

// --- Brute force -------------------------------------------------------------------------------

// Signed distance to a tube with radius interpolated along each segment:
// min over segments and s of |p - c(s)| - r(s) (convex in s: ternary search).
double segmentSignedDistance(const CenterlinePoint& a, const CenterlinePoint& b, glm::dvec3 p) {
  return test_support::taperedSegmentSignedDistance(a.positionMm, a.radiusMm, b.positionMm, b.radiusMm,
                                                    p);
}

double pointSegmentDistance(glm::dvec3 a, glm::dvec3 b, glm::dvec3 p) {
  const glm::dvec3 along = b - a;
  const double lengthSquared = glm::dot(along, along);
  const double s =
      lengthSquared > 0 ? std::clamp(glm::dot(p - a, along) / lengthSquared, 0.0, 1.0) : 0.0;
  return glm::distance(p, a + s * along);
}

struct BruteForceTube {
  std::vector<std::pair<CenterlinePoint, CenterlinePoint>> segments;

  explicit BruteForceTube(const std::vector<CenterlinePath>& paths) {
    for (const CenterlinePath& path : paths) {
      for (std::size_t n = 0; n + 1 < path.points.size(); ++n) {
        segments.push_back({path.points[n], path.points[n + 1]});
      }
    }
  }

  // The segments that may come within `reachMm` of the ray of pixel (h, v) (image-space distance
  // of the projected segment, a lower bound of the 3-D distance, minus the larger radius).
  std::vector<std::size_t> near(const ViewGeometry& view, double h, double v, double reachMm) const {
    std::vector<std::size_t> found;
    const auto project = [&](glm::dvec3 p) {
      return glm::dvec3(glm::dot(p - view.centre, view.right), glm::dot(p - view.centre, view.up), 0);
    };
    for (std::size_t n = 0; n < segments.size(); ++n) {
      const auto& [a, b] = segments[n];
      const double distance =
          pointSegmentDistance(project(a.positionMm), project(b.positionMm), {h, v, 0});
      if (distance - std::max(a.radiusMm, b.radiusMm) <= reachMm) found.push_back(n);
    }
    return found;
  }

  // Exact when below `farMm`; above it only a lower bound is returned.
  double signedDistance(glm::dvec3 p, const std::vector<std::size_t>& candidates, double farMm) const {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t n : candidates) {
      const auto& [a, b] = segments[n];
      const double bound =
          pointSegmentDistance(a.positionMm, b.positionMm, p) - std::max(a.radiusMm, b.radiusMm);
      if (bound > std::min(best, farMm)) {
        best = std::min(best, bound);
        continue;
      }
      best = std::min(best, segmentSignedDistance(a, b, p));
    }
    return best;
  }
};

// Dense points along the paths (at most 0.01 mm apart), in view coordinates (h, v, t).
std::vector<glm::dvec3> densePointsInView(const std::vector<CenterlinePath>& paths,
                                          const ViewGeometry& view) {
  std::vector<glm::dvec3> points;
  for (const CenterlinePath& path : paths) {
    for (std::size_t n = 0; n + 1 < path.points.size(); ++n) {
      const glm::dvec3 a = path.points[n].positionMm, b = path.points[n + 1].positionMm;
      const int steps = std::max(1, int(std::ceil(glm::distance(a, b) / 0.01)));
      for (int k = 0; k <= steps; ++k) {
        const glm::dvec3 p = glm::mix(a, b, double(k) / steps) - view.centre;
        points.push_back({glm::dot(p, view.right), glm::dot(p, view.up), glm::dot(p, view.viewDir)});
      }
    }
  }
  return points;
}

// Union of [t - front, t + back] over the dense points with |v_c - v| <= D/2 + grow and
// |h_c - h| <= halfWidth + grow, each interval grown by `grow` at both ends. With grow < 0 a
// subset of the slab, with grow > 0 (and points 0.01 mm apart, grow >= 0.005) a superset.
std::vector<DepthSpan> expectedSlab(const std::vector<glm::dvec3>& rowPoints, const SlabContext& slab,
                                    double h, double grow) {
  std::vector<double> depths;
  for (const glm::dvec3& c : rowPoints) {
    if (std::abs(c.x - h) <= slab.halfWidthMm + grow) depths.push_back(c.z);
  }
  std::sort(depths.begin(), depths.end());
  std::vector<DepthSpan> spans;
  for (double t : depths) {
    const DepthSpan span{t - slab.frontMm - grow, t + slab.backMm + grow};
    if (!spans.empty() && span.begin <= spans.back().end) {
      spans.back().end = std::max(spans.back().end, span.end);
    } else if (!span.empty()) {
      spans.push_back(span);
    }
  }
  return spans;
}

// Whether pixel position (h, v) lies in an end cap of one of the paths (vessel_glyph.cpp,
// SlabCap): beyond an end, within the half width along the end segment's image-space direction and
// across it. `grow` widens the rectangle on every side (narrows it when negative).
bool inEndCap(const std::vector<CenterlinePath>& paths, const ViewGeometry& view, glm::dvec2 pixel,
              double halfWidthMm, double grow) {
  const auto inCap = [&](glm::dvec3 end, glm::dvec3 inward) {
    const glm::dvec2 e = imagePosition(view, end);
    const glm::dvec2 outward = glm::normalize(e - imagePosition(view, inward));
    const double along = glm::dot(pixel - e, outward);
    const double across = glm::dot(pixel - e, glm::dvec2(-outward.y, outward.x));
    return along >= -grow && along <= halfWidthMm + grow && std::abs(across) <= halfWidthMm + grow;
  };
  for (const CenterlinePath& path : paths) {
    const auto& p = path.points;
    if (p.size() < 2) continue;
    if (inCap(p[0].positionMm, p[1].positionMm)) return true;
    if (inCap(p.back().positionMm, p[p.size() - 2].positionMm)) return true;
  }
  return false;
}

std::vector<glm::dvec3> pointsInRow(const std::vector<glm::dvec3>& dense, double v, double halfHeight) {
  std::vector<glm::dvec3> found;
  for (const glm::dvec3& c : dense) {
    if (std::abs(c.y - v) <= halfHeight) found.push_back(c);
  }
  return found;
}

bool inSpans(const std::vector<DepthSpan>& spans, double t) {
  return std::any_of(spans.begin(), spans.end(),
                     [&](const DepthSpan& s) { return s.begin <= t && t <= s.end; });
}

// Samples every ray every 0.2 mm: a point deeper than `tolerance` inside the tube must be focus,
// one farther than `outerSlackMm` + tolerance outside must not; with a slab, a point well inside
// the expected slab (and outside the tube and the end caps) must be context, one well outside it
// must not.
void expectMatchesBruteForce(const std::vector<CenterlinePath>& paths, double angleDeg,
                             const VesselGlyphSettings& settings, double outerSlackMm) {
  constexpr double kTolerance = 0.01;
  const Volume volume = testVolume();
  const ViewGeometry view = viewAt(volume, angleDeg);
  const RayRegions regions = buildRayRegions(volume, view, inVolumeFrame(paths), settings);
  expectWellFormed(regions, view);
  const BruteForceTube tube(paths);
  const bool slab = settings.context == ContextShape::slab;
  const std::vector<glm::dvec3> dense =
      slab ? densePointsInView(paths, view) : std::vector<glm::dvec3>{};
  const double far = outerSlackMm + kTolerance;
  int focusChecked = 0, contextChecked = 0, outsideChecked = 0;
  for (int y = 0; y < view.height; ++y) {
    const double v = (view.height * 0.5 - y - 0.5) * view.pixelMm;
    const auto rowInner = pointsInRow(dense, v, view.pixelMm / 2 - kTolerance);
    const auto rowOuter = pointsInRow(dense, v, view.pixelMm / 2 + kTolerance);
    for (int x = 0; x < view.width; ++x) {
      const auto intervals = intervalsOf(regions, {x, y});
      const glm::dvec3 origin = view.rayOrigin(x, y);
      const double h = (x + 0.5 - view.width * 0.5) * view.pixelMm;
      const auto candidates = tube.near(view, h, v, far);
      const double w = settings.slab.halfWidthMm;
      const auto slabInner = inEndCap(paths, view, {h, v}, w, kTolerance)
                                 ? std::vector<DepthSpan>{}
                                 : expectedSlab(rowInner, settings.slab, h, -kTolerance);
      const auto slabOuter = inEndCap(paths, view, {h, v}, w, -kTolerance)
                                 ? std::vector<DepthSpan>{}
                                 : expectedSlab(rowOuter, settings.slab, h, kTolerance);
      if (candidates.empty() && slabOuter.empty()) {  // nothing can reach this ray
        ASSERT_TRUE(intervals.empty()) << "pixel (" << x << ", " << y << ")";
        ++outsideChecked;
        continue;
      }
      for (double t = -60; t <= 60; t += 0.2) {
        const double distance = tube.signedDistance(origin + t * view.viewDir, candidates, far);
        const Region region = regionAt(intervals, t);
        if (distance < -kTolerance) {
          ++focusChecked;
          ASSERT_EQ(region, Region::focus) << "inside the tube at pixel (" << x << ", " << y
                                           << "), t = " << t << ", distance " << distance;
        } else if (distance > far) {
          ASSERT_NE(region, Region::focus) << "outside the tube at pixel (" << x << ", " << y
                                           << "), t = " << t << ", distance " << distance;
          if (inSpans(slabInner, t)) {
            ++contextChecked;
            ASSERT_EQ(region, Region::context)
                << "inside the slab at pixel (" << x << ", " << y << "), t = " << t;
          } else if (!inSpans(slabOuter, t)) {
            ASSERT_EQ(region, Region::outside)
                << "outside the slab at pixel (" << x << ", " << y << "), t = " << t;
          }
        }
      }
    }
  }
  EXPECT_GT(focusChecked, 1000);
  EXPECT_GT(outsideChecked, 100);
  if (slab) {
    EXPECT_GT(contextChecked, 10000);
  }
}

// --- Straight vessel along the rotation axis: closed forms --------------------------------------

TEST(VesselGlyph, VesselAlongTheAxisHasTheChordAsFocusAtEveryAngle) {
  constexpr double kRadius = 3.5;
  const Volume volume = testVolume();
  const glm::dvec3 from(40, 25, 5), to(40, 25, 73);
  const Centerlines centerlines = inVolumeFrame({straightPath("axial", from, to, 50, kRadius)});
  for (int step = 0; step < 36; ++step) {
    const ViewGeometry view = viewAt(volume, step * 10.0);
    const RayRegions regions = buildRayRegions(volume, view, centerlines, exactFocusOnly());
    expectWellFormed(regions, view);
    const glm::dvec3 c = from - view.centre;
    const double tCentre = glm::dot(c, view.viewDir);
    // Rows well inside the vessel's z-range (no caps): z in [20, 58] mm.
    for (int y = 0; y < view.height; ++y) {
      const double z = view.rayOrigin(0, y).z;
      if (z < 20 || z > 58) continue;
      int withFocus = 0;
      for (int x = 0; x < view.width; ++x) {
        const double offset = std::abs(glm::dot(view.rayOrigin(x, y) - from, view.right));
        const auto focus = ofRegion(intervalsOf(regions, {x, y}), Region::focus);
        if (offset > kRadius + 1e-6) {
          ASSERT_TRUE(focus.empty()) << "angle " << step * 10 << ", pixel " << x << ", " << y;
          continue;
        }
        if (offset > kRadius - 1e-6) continue;
        ++withFocus;
        ASSERT_EQ(focus.size(), 1u) << "angle " << step * 10 << ", pixel " << x << ", " << y;
        const double half = std::sqrt(kRadius * kRadius - offset * offset);
        EXPECT_NEAR(focus[0].begin, tCentre - half, 1e-4);
        EXPECT_NEAR(focus[0].end, tCentre + half, 1e-4);
        if (offset <= view.pixelMm / 2) {  // the column through the centre: depth 2R about t_c
          EXPECT_LE(focus[0].end - focus[0].begin, 2 * kRadius + 1e-4);
          EXPECT_GE(focus[0].end - focus[0].begin, 2 * std::sqrt(kRadius * kRadius - 0.25) - 1e-4);
          EXPECT_NEAR((focus[0].begin + focus[0].end) / 2, tCentre, 1e-4);
        }
      }
      // Columns are 1 mm apart: a 7 mm wide vessel covers 7 of them (6 or 8 at the edges).
      ASSERT_GE(withFocus, 6) << "angle " << step * 10 << ", row " << y;
      ASSERT_LE(withFocus, 8);
    }
  }
}

// --- Brute force: horizontal, oblique/tortuous, crossing ----------------------------------------

TEST(VesselGlyph, HorizontalVesselIsEnclosedCompletely) {
  const std::vector<CenterlinePath> paths{
      straightPath("horizontal", {6, 32, 40}, {57, 30, 41}, 60, 4.0)};
  for (double angle : {0.0, 30.0, 90.0, 135.0, 250.0}) {
    SCOPED_TRACE("angle " + std::to_string(angle));
    expectMatchesBruteForce(paths, angle, exactFocusOnly(), 0.0);
    if (HasFatalFailure()) return;
  }
}

TEST(VesselGlyph, ObliqueTortuousVesselMatchesBruteForce) {
  for (double angle : {0.0, 37.0, 90.0, 143.0, 211.0, 300.0}) {
    SCOPED_TRACE("angle " + std::to_string(angle));
    expectMatchesBruteForce({tortuousPath()}, angle, exactFocusOnly(), 0.0);
    if (HasFatalFailure()) return;
  }
}

TEST(VesselGlyph, OverlappingTubesOfSeveralPathsAreMerged) {
  const std::vector<CenterlinePath> paths{straightPath("a", {10, 20, 10}, {50, 40, 70}, 30, 5.0),
                                          straightPath("b", {50, 20, 10}, {12, 42, 68}, 25, 3.0),
                                          straightPath("c", {30, 10, 40}, {30, 55, 40}, 20, 4.0)};
  for (double angle : {0.0, 45.0, 100.0}) {
    SCOPED_TRACE("angle " + std::to_string(angle));
    expectMatchesBruteForce(paths, angle, exactFocusOnly(), 0.0);
    if (HasFatalFailure()) return;
  }
}

// --- Context slab --------------------------------------------------------------------------------

TEST(VesselGlyph, SlabContextFollowsTheCenterlineDepthWithinItsBounds) {
  const VesselGlyphSettings settings = exactFocusInSlab({6.0, 9.0, 12.0});
  // Slanted in depth at angle 0 (y changes with z), and a tortuous one.
  const std::vector<CenterlinePath> slanted{straightPath("slanted", {30, 18, 5}, {34, 45, 73}, 40, 2.0)};
  for (double angle : {0.0, 60.0, 145.0}) {
    SCOPED_TRACE("slanted, angle " + std::to_string(angle));
    expectMatchesBruteForce(slanted, angle, settings, 0.0);
    if (HasFatalFailure()) return;
  }
  for (double angle : {20.0, 200.0}) {
    SCOPED_TRACE("tortuous, angle " + std::to_string(angle));
    expectMatchesBruteForce({tortuousPath()}, angle, settings, 0.0);
    if (HasFatalFailure()) return;
  }
}

TEST(VesselGlyph, SlabIsBoundedSideways) {
  VesselGlyphSettings settings = exactFocusInSlab({5.0, 5.0, 8.0});
  const Volume volume = testVolume();
  const ViewGeometry view = viewAt(volume, 0);  // h = x - 31.5, t = y - 31.5
  const Centerlines centerlines =
      inVolumeFrame({straightPath("axial", {30.5, 25, 5}, {30.5, 25, 73}, 30, 2.0)});
  const RayRegions regions = buildRayRegions(volume, view, centerlines, settings);
  const int y = view.height / 2;
  for (int x = 0; x < view.width; ++x) {
    const double h = (x + 0.5 - view.width * 0.5) * view.pixelMm;  // centerline at h = -1
    const auto context = ofRegion(intervalsOf(regions, {x, y}), Region::context);
    if (std::abs(h + 1) > 8) {
      EXPECT_TRUE(context.empty()) << "x " << x;
    } else if (std::abs(h + 1) > 2) {  // beside the focus: the whole slab, depth 25 - 31.5 -5 / +5
      ASSERT_EQ(context.size(), 1u) << "x " << x;
      EXPECT_NEAR(context[0].begin, -6.5 - 5, 1e-4);
      EXPECT_NEAR(context[0].end, -6.5 + 5, 1e-4);
    }
  }
  settings.slab.halfWidthMm = std::numeric_limits<double>::infinity();  // the thesis's slab
  const RayRegions unbounded = buildRayRegions(volume, view, centerlines, settings);
  for (int x : {0, view.width - 1}) {
    const auto context = ofRegion(intervalsOf(unbounded, {x, y}), Region::context);
    ASSERT_EQ(context.size(), 1u);
    EXPECT_NEAR(context[0].begin, -11.5, 1e-4);
  }
}

// A path that runs sideways in the image has its points in few rows, and those reach the half
// width sideways, i.e. along the path: without end caps, past its ends as a needle of one to a few
// rows (thesis 5.3.3: the row-wise sweep assumes vessels run vertically).
TEST(VesselGlyph, SlabEndsAtThePathsEnds) {
  const VesselGlyphSettings settings = exactFocusInSlab({5.0, 5.0, 8.0});
  const Volume volume = testVolume();
  const ViewGeometry view = viewAt(volume, 0);  // h = x - 31.5, v = z - 39.375
  struct Case {
    const char* name;
    glm::dvec3 from, to;
  };
  for (const Case& path :
       {Case{"horizontal", {20, 30, 40}, {44, 30, 40}}, Case{"oblique", {16, 30, 24}, {44, 30, 52}}}) {
    SCOPED_TRACE(path.name);
    const CenterlinePath centerline = straightPath(path.name, path.from, path.to, 13, 1.5);
    const RayRegions regions = buildRayRegions(volume, view, inVolumeFrame({centerline}), settings);
    const glm::dvec2 start = imagePosition(view, path.from), end = imagePosition(view, path.to);
    const glm::dvec2 along = glm::normalize(end - start);
    int withContext = 0, beforeStart = 0, pastEnd = 0;
    for (int y = 0; y < view.height; ++y) {
      for (int x = 0; x < view.width; ++x) {
        if (ofRegion(intervalsOf(regions, {x, y}), Region::context).empty()) continue;
        ++withContext;
        const glm::dvec2 pixel = pixelPosition(view, {x, y});
        beforeStart += glm::dot(pixel - start, along) < -1e-9;
        pastEnd += glm::dot(pixel - end, along) > 1e-9;
      }
    }
    EXPECT_EQ(beforeStart, 0);
    EXPECT_EQ(pastEnd, 0);
    EXPECT_GT(withContext, 20);  // the slab is still there between the ends
  }
}

TEST(VesselGlyph, ContextTubeSurroundsTheFocus) {
  VesselGlyphSettings settings = exactFocusOnly();
  settings.context = ContextShape::tube;
  settings.contextTube = {RadiusMode::constant, 9.0, 0.0};
  const Volume volume = testVolume();
  const ViewGeometry view = viewAt(volume, 0);
  const Centerlines centerlines =
      inVolumeFrame({straightPath("axial", {31.5, 25, 5}, {31.5, 25, 73}, 30, 2.0)});
  const RayRegions regions = buildRayRegions(volume, view, centerlines, settings);
  const int y = view.height / 2, xCentre = view.width / 2;  // h = 0.5 at xCentre
  const auto centre = intervalsOf(regions, {xCentre, y});
  ASSERT_EQ(centre.size(), 3u);  // context, focus, context
  const double focusHalf = std::sqrt(4 - 0.25), contextHalf = std::sqrt(81 - 0.25);
  EXPECT_EQ(centre[0].region, Region::context);
  EXPECT_NEAR(centre[0].begin, -6.5 - contextHalf, 1e-4);
  EXPECT_NEAR(centre[0].end, -6.5 - focusHalf, 1e-4);
  EXPECT_EQ(centre[1].region, Region::focus);
  EXPECT_EQ(centre[2].region, Region::context);
  EXPECT_NEAR(centre[2].end, -6.5 + contextHalf, 1e-4);
  EXPECT_TRUE(intervalsOf(regions, {xCentre + 10, y}).empty());  // h = 10.5 > 9
}

// --- Cleft and half-vessel -----------------------------------------------------------------------

TEST(VesselGlyph, CleftRemovesTheContextInFrontOfTheFocusInsideItsFootprint) {
  VesselGlyphSettings settings = exactFocusOnly();
  settings.context = ContextShape::slab;
  settings.slab = {20.0, 20.0, 30.0};
  const Volume volume = testVolume();
  const Centerlines centerlines =
      inVolumeFrame({tortuousPath(), straightPath("axial", {40, 25, 5}, {40, 25, 73}, 30, 3.0)});
  for (double angle : {0.0, 70.0, 160.0}) {
    const ViewGeometry view = viewAt(volume, angle);
    settings.cleft = false;
    const RayRegions plain = buildRayRegions(volume, view, centerlines, settings);
    settings.cleft = true;
    const RayRegions cleft = buildRayRegions(volume, view, centerlines, settings);
    expectWellFormed(cleft, view);
    int footprint = 0, plainContextInFront = 0;
    for (int y = 0; y < view.height; ++y) {
      for (int x = 0; x < view.width; ++x) {
        const auto before = intervalsOf(plain, {x, y}), after = intervalsOf(cleft, {x, y});
        const auto focus = ofRegion(after, Region::focus);
        ASSERT_EQ(focus.size(), ofRegion(before, Region::focus).size());
        if (focus.empty()) {  // outside the footprint nothing changes
          ASSERT_EQ(after.size(), before.size());
          continue;
        }
        ++footprint;
        const float entry = focus.front().begin;
        for (const RegionInterval& context : ofRegion(after, Region::context)) {
          ASSERT_GE(context.begin, entry) << "context in front of the focus at " << x << ", " << y;
        }
        plainContextInFront += !before.empty() && before.front().region == Region::context;
        // Behind the entry the cleft changes nothing.
        for (double t = entry; t < 60; t += 0.25) {
          ASSERT_EQ(regionAt(after, t), regionAt(before, t));
        }
      }
    }
    EXPECT_GT(footprint, 300);
    EXPECT_GT(plainContextInFront, footprint / 2);  // the slab reaches 20 mm in front: there was some
  }
}

TEST(VesselGlyph, HalfVesselCutKeepsTheBackHalf) {
  VesselGlyphSettings settings = exactFocusOnly();
  settings.halfVessel = true;
  const Volume volume = testVolume();
  constexpr double kRadius = 3.0;
  const glm::dvec3 axialFrom(40, 25, 5), horizontalFrom(8, 45, 40), horizontalTo(56, 45, 40);
  const Centerlines centerlines =
      inVolumeFrame({straightPath("axial", axialFrom, {40, 25, 73}, 30, kRadius),
                     straightPath("horizontal", horizontalFrom, horizontalTo, 30, kRadius)});
  for (double angle : {0.0, 30.0, 115.0}) {
    const ViewGeometry view = viewAt(volume, angle);
    const RayRegions regions = buildRayRegions(volume, view, centerlines, settings);
    expectWellFormed(regions, view);
    int checked = 0;
    for (int y = 0; y < view.height; ++y) {
      for (int x = 0; x < view.width; ++x) {
        const auto focus = ofRegion(intervalsOf(regions, {x, y}), Region::focus);
        const glm::dvec3 origin = view.rayOrigin(x, y);
        const double z = origin.z;
        const glm::dvec3 toAxial = origin - axialFrom;
        const double axialOffset = std::abs(glm::dot(toAxial, view.right));
        const double axialDepth = -glm::dot(toAxial, view.viewDir);
        // The horizontal vessel's centerline point under this pixel: same h along its projection.
        const glm::dvec3 along = horizontalTo - horizontalFrom;
        const double s = glm::dot(origin - horizontalFrom, view.right) / glm::dot(along, view.right);
        const glm::dvec3 under = horizontalFrom + s * along;
        const double horizontalDepth = glm::dot(under - origin, view.viewDir);
        const double horizontalOffset = std::abs(z - 40);
        const bool nearAxial =
            axialOffset < kRadius - 0.01 && z > 15 && z < 60 && std::abs(z - 40) > kRadius + 1;
        const bool nearHorizontal =
            horizontalOffset < kRadius - 0.01 && s > 0.1 && s < 0.9 && axialOffset > kRadius + 1;
        if (nearAxial) {
          ASSERT_EQ(focus.size(), 1u) << x << ", " << y;
          EXPECT_NEAR(focus[0].begin, axialDepth, 1e-4);
          EXPECT_NEAR(focus[0].end,
                      axialDepth + std::sqrt(kRadius * kRadius - axialOffset * axialOffset), 1e-4);
          ++checked;
        } else if (nearHorizontal) {
          ASSERT_EQ(focus.size(), 1u) << x << ", " << y;
          EXPECT_NEAR(focus[0].begin, horizontalDepth, 1e-4) << "angle " << angle;
          ++checked;
        }
      }
    }
    EXPECT_GT(checked, 150);
  }
}

// --- Shared trunks, simplification, settings, determinism ---------------------------------------

TEST(VesselGlyph, SharedTrunkIsCountedOnce) {
  const CenterlinePath trunk = straightPath("trunk", {32, 30, 70}, {32, 30, 40}, 31, 5.0);
  CenterlinePath left = trunk, right = trunk;
  left.name = "left";
  right.name = "right";
  for (int n = 1; n <= 20; ++n) {
    left.points.push_back({{32 - n, 30, 40 - n}, 3.0});
    right.points.push_back({{32 + n, 30, 40 - n}, 3.0});
  }
  VesselGlyphSettings settings = exactFocusOnly();
  settings.context = ContextShape::slab;
  const GlyphTubes tubes = prepareGlyphTubes(inVolumeFrame({left, right}), settings);
  ASSERT_EQ(tubes.chains.size(), 2u);
  EXPECT_EQ(tubes.chains[0].size(), left.points.size());
  ASSERT_EQ(tubes.chains[1].size(), 21u);  // from the bifurcation point on
  EXPECT_EQ(tubes.chains[1].front().positionMm, glm::dvec3(32, 30, 40));

  // The same regions as the trunk given once.
  CenterlinePath branchOnly{"right branch", {right.points.begin() + 30, right.points.end()}};
  const Volume volume = testVolume();
  const ViewGeometry view = viewAt(volume, 50);
  const RayRegions once = buildRayRegions(volume, view, inVolumeFrame({left, branchOnly}), settings);
  const RayRegions repeated = buildRayRegions(volume, view, inVolumeFrame({left, right}), settings);
  EXPECT_EQ(once.rayBegin, repeated.rayBegin);
  ASSERT_EQ(once.intervals.size(), repeated.intervals.size());
  for (std::size_t n = 0; n < once.intervals.size(); ++n) {
    ASSERT_EQ(once.intervals[n].begin, repeated.intervals[n].begin);
    ASSERT_EQ(once.intervals[n].end, repeated.intervals[n].end);
  }
}

TEST(VesselGlyph, SimplificationMergesCollinearPointsAndStaysWithinTolerance) {
  const VesselGlyphSettings settings = simplifiedFocusOnly(0.1);
  const GlyphTubes straight = prepareGlyphTubes(
      inVolumeFrame({straightPath("dense", {10, 10, 10}, {50, 50, 60}, 1000, 3.0)}), settings);
  ASSERT_NO_FATAL_FAILURE(expectOneSegmentPerPiece(straight, 1000));
  EXPECT_NEAR(straight.chains[0][0].focusRadiusMm, 3.1, 1e-12);  // grown by the tolerance

  const GlyphTubes tortuous = prepareGlyphTubes(inVolumeFrame({tortuousPath()}), settings);
  EXPECT_LT(tortuous.chains[0].size(), tortuousPath().points.size());
  // Holds the exact tube; lies within twice the tolerance of it.
  for (double angle : {10.0, 120.0}) {
    SCOPED_TRACE("angle " + std::to_string(angle));
    expectMatchesBruteForce({tortuousPath()}, angle, settings, 2 * settings.simplifyToleranceMm);
    if (HasFatalFailure()) return;
  }
}

TEST(VesselGlyph, LongPathsAreSimplifiedPieceByPiece) {
  const GlyphTubes tubes =
      prepareGlyphTubes(inVolumeFrame({straightPath("long", {10, 10, 5}, {50, 50, 70}, 2000, 2.0)}),
                        simplifiedFocusOnly(0.1));
  expectOneSegmentPerPiece(tubes, 2000);
}

TEST(VesselGlyph, NoCenterlinesOrSinglePointsGiveEmptyRaysOrBalls) {
  const Volume volume = testVolume();
  const ViewGeometry view = viewAt(volume, 20);
  VesselGlyphSettings settings = exactFocusOnly();
  const RayRegions none = buildRayRegions(volume, view, inVolumeFrame({}), settings);
  expectWellFormed(none, view);
  EXPECT_TRUE(none.intervals.empty());
  // A path of one point is a ball of its radius.
  const RayRegions ball = buildRayRegions(
      volume, view, inVolumeFrame({CenterlinePath{"dot", {{{31.5, 31.5, 39.375}, 4.0}}}}), settings);
  expectWellFormed(ball, view);
  const auto centre = ofRegion(intervalsOf(ball, {view.width / 2, view.height / 2}), Region::focus);
  ASSERT_EQ(centre.size(), 1u);  // h = 0.5 mm, v = 0 (the image is 90 x 79)
  EXPECT_NEAR(centre[0].end - centre[0].begin, 2 * std::sqrt(16 - 0.25), 1e-4);
  EXPECT_NEAR(centre[0].begin + centre[0].end, 0.0, 1e-4);  // centred on depth 0
  EXPECT_TRUE(intervalsOf(ball, {view.width / 2 + 5, view.height / 2}).empty());
}

TEST(VesselGlyph, FocusRadiusModesAndUnknownRadius) {
  CenterlinePath path = straightPath("p", {10, 10, 10}, {20, 10, 10}, 3, 2.0);
  path.points[1].radiusMm = 0;  // unknown
  VesselGlyphSettings settings = exactFocusOnly();
  settings.focus = {RadiusMode::vesselFactor, 1.5, 0.5};
  settings.unknownVesselRadiusMm = 4.0;
  const GlyphTubes factor = prepareGlyphTubes(inVolumeFrame({path}), settings);
  ASSERT_EQ(factor.chains.at(0).size(), 3u);
  EXPECT_DOUBLE_EQ(factor.chains[0][0].focusRadiusMm, 3.5);
  EXPECT_DOUBLE_EQ(factor.chains[0][1].focusRadiusMm, 6.5);
  settings.focus = {RadiusMode::constant, 2.5, 0.0};
  EXPECT_DOUBLE_EQ(prepareGlyphTubes(inVolumeFrame({path}), settings).chains[0][1].focusRadiusMm, 2.5);
}

TEST(VesselGlyph, RejectsBadSettingsAndFrames) {
  const Volume volume = testVolume();
  const ViewGeometry view = viewAt(volume, 0);
  const Centerlines centerlines = inVolumeFrame({straightPath("p", {10, 10, 10}, {20, 10, 10}, 3, 2.0)});
  VesselGlyphSettings settings;
  settings.slab.frontMm = -1;
  EXPECT_TRUE(settingsProblem(settings).has_value());
  EXPECT_THROW(buildRayRegions(volume, view, centerlines, settings), std::invalid_argument);
  settings = {};
  settings.focus.value = std::nan("");
  EXPECT_THROW(buildRayRegions(volume, view, centerlines, settings), std::invalid_argument);
  settings = {};
  EXPECT_FALSE(settingsProblem(settings).has_value());
  Centerlines physical = centerlines;
  physical.frame = CenterlineFrame::physical;
  EXPECT_THROW(buildRayRegions(volume, view, physical, settings), std::logic_error);
  const Volume other = makeVolume({32, 32, 32}, {1.0, 1.0, 1.0});
  EXPECT_THROW(buildRayRegions(other, view, centerlines, settings), std::invalid_argument);
}

TEST(VesselGlyph, NonFinitePointsSplitThePathInsteadOfFailing) {
  CenterlinePath path = straightPath("p", {10, 30, 10}, {10, 30, 70}, 7, 3.0);
  path.points[3].positionMm.x = std::nan("");
  const Volume volume = testVolume();
  const ViewGeometry view = viewAt(volume, 0);
  VesselGlyphSettings settings = exactFocusOnly();
  EXPECT_EQ(prepareGlyphTubes(inVolumeFrame({path}), settings).chains.size(), 2u);
  expectWellFormed(buildRayRegions(volume, view, inVolumeFrame({path}), settings), view);
}

TEST(VesselGlyph, SameOutputWhateverTheThreadCount) {
  VesselGlyphSettings settings;
  settings.context = ContextShape::slab;
  settings.cleft = true;
  const Volume volume = testVolume();
  const Centerlines centerlines =
      inVolumeFrame({tortuousPath(), straightPath("a", {10, 20, 10}, {50, 40, 70}, 300, 5.0),
                     straightPath("b", {50, 20, 10}, {12, 42, 68}, 200, 3.0)});
  const ViewGeometry view = viewAt(volume, 33);
  const auto buildWith = [&](int threads) {
    tbb::task_arena arena(threads);
    RayRegions regions;
    arena.execute([&] { regions = buildRayRegions(volume, view, centerlines, settings); });
    return regions;
  };
  const RayRegions one = buildWith(1), two = buildWith(2), again = buildWith(2);
  ASSERT_GT(one.intervals.size(), 1000u);
  for (const RayRegions* other : {&two, &again}) {
    ASSERT_EQ(one.rayBegin, other->rayBegin);
    ASSERT_EQ(one.intervals.size(), other->intervals.size());
    for (std::size_t n = 0; n < one.intervals.size(); ++n) {
      ASSERT_EQ(one.intervals[n].begin, other->intervals[n].begin);
      ASSERT_EQ(one.intervals[n].end, other->intervals[n].end);
      ASSERT_EQ(one.intervals[n].region, other->intervals[n].region);
    }
  }
}

TEST(VesselGlyph, BuilderReusingItsMemoryGivesTheSameRegions) {
  VesselGlyphSettings settings;
  settings.context = ContextShape::slab;
  const Volume volume = testVolume();
  const Centerlines centerlines =
      inVolumeFrame({tortuousPath(), straightPath("a", {10, 20, 10}, {50, 40, 70}, 300, 5.0)});
  RayRegionBuilder builder(centerlines, settings);
  RayRegions reused;
  for (double angle : {0.0, 45.0, 90.0, 10.0}) {  // bigger and smaller outputs in turn
    const ViewGeometry view = viewAt(volume, angle);
    builder.build(view, reused);
    const RayRegions fresh = buildRayRegions(volume, view, centerlines, settings);
    ASSERT_EQ(reused.width, fresh.width);
    ASSERT_EQ(reused.rayBegin, fresh.rayBegin) << "angle " << angle;
    ASSERT_EQ(reused.intervals.size(), fresh.intervals.size());
    for (std::size_t n = 0; n < fresh.intervals.size(); ++n) {
      ASSERT_EQ(reused.intervals[n].begin, fresh.intervals[n].begin);
      ASSERT_EQ(reused.intervals[n].end, fresh.intervals[n].end);
      ASSERT_EQ(reused.intervals[n].region, fresh.intervals[n].region);
    }
  }
}

}  // namespace
}  // namespace angio
