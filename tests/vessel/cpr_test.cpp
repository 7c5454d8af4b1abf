// Curved planar reformation (Kanitsar et al., IEEE Vis 2002): the three projections' geometry
// against the math, bands of synthetic tubes, registration with the DVR view, multi-path trunks,
// resampling against the trilinear reference (and the OpenCV remap comparison), the real aorta,
// display and errors.
#include "vessel/cpr.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "phantom/phantom.h"
#include "core/volume_sampling.h"
#include "core/voxel.h"
#include "io/centerline_file.h"
#include "io/volume_reader.h"

namespace angio {
namespace {

constexpr double kPi = std::numbers::pi;

// --- Synthetic data -----------------------------------------------------------------------------

CenterlinePath polyline(const std::string& name, const std::function<glm::dvec3(double)>& curve,
                        int points, double radiusMm) {
  CenterlinePath path{name, {}};
  for (int n = 0; n < points; ++n) path.points.push_back({curve(double(n) / (points - 1)), radiusMm});
  return path;
}

CenterlinePath straightPath(glm::dvec3 from, glm::dvec3 to, int points = 50, double radius = 5) {
  return polyline(
      "straight", [&](double t) { return glm::mix(from, to, t); }, points, radius);
}

double distanceToSegment(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b) {
  const glm::dvec3 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::distance(p, a + t * ab);
}

double distanceToPath(glm::dvec3 p, const CenterlinePath& path) {
  double best = std::numeric_limits<double>::max();
  for (std::size_t n = 0; n + 1 < path.points.size(); ++n) {
    best =
        std::min(best, distanceToSegment(p, path.points[n].positionMm, path.points[n + 1].positionMm));
  }
  return best;
}

// The points of a path within `windowMm` of arc length around arcMm.
CenterlinePath pathPiece(const CenterlinePath& path, double arcMm, double windowMm) {
  const std::vector<double> arc = arcLengthsMm(path);
  CenterlinePath piece{path.name, {}};
  for (std::size_t n = 0; n < arc.size(); ++n) {
    if (std::abs(arc[n] - arcMm) <= windowMm) piece.points.push_back(path.points[n]);
  }
  return piece;
}

bool insideTube(glm::dvec3 p, const std::vector<CenterlinePath>& paths, double radiusMm) {
  return std::any_of(paths.begin(), paths.end(),
                     [&](const CenterlinePath& path) { return distanceToPath(p, path) < radiusMm; });
}

// The share of a voxel inside the tube, from 4x4x4 sub-samples.
double insideFraction(glm::dvec3 centre, glm::dvec3 spacing, const std::vector<CenterlinePath>& paths,
                      double radiusMm) {
  int inside = 0;
  for (int s = 0; s < 64; ++s) {
    const glm::dvec3 offset{s % 4 - 1.5, s / 4 % 4 - 1.5, s / 16 - 1.5};
    inside += insideTube(centre + offset * spacing / 4.0, paths, radiusMm);
  }
  return inside / 64.0;
}

// A tube of `radiusMm` around the paths, lumenHu inside and backgroundHu outside, with partial
// volume at the wall, so the trilinear 50 % level sits at the wall (to about 0.1 voxel).
Volume tubeVolume(glm::ivec3 dims, glm::dvec3 spacing, const std::vector<CenterlinePath>& paths,
                  double radiusMm, double lumenHu = 400, double backgroundHu = 0) {
  Volume volume = makeVolume(dims, spacing, encodeVoxel(backgroundHu));
  const double reach = radiusMm + glm::length(spacing);
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        const glm::dvec3 centre = glm::dvec3(i, j, k) * spacing;
        if (!insideTube(centre, paths, reach)) continue;
        const double fraction = insideFraction(centre, spacing, paths, radiusMm);
        volume.voxels[volume.indexOf(i, j, k)] =
            encodeVoxel(backgroundHu + (lumenHu - backgroundHu) * fraction);
      }
  return volume;
}

Volume emptyVolume(glm::ivec3 dims = {60, 60, 100}, glm::dvec3 spacing = glm::dvec3(1.0)) {
  return makeVolume(dims, spacing, encodeVoxel(0));
}

// The columns of row y whose HU exceeds the threshold: [first, last], or {-1, -1}.
std::pair<int, int> brightRun(const Cpr& cpr, int y, float threshold) {
  int first = -1, last = -1;
  for (int x = 0; x < cpr.layout.width; ++x) {
    const float hu = cpr.huAt(x, y);
    if (!std::isnan(hu) && hu > threshold) {
      if (first < 0) first = x;
      last = x;
    }
  }
  return {first, last};
}

std::vector<const CprSpan*> spansOfRow(const CprLayout& layout, int row) {
  std::vector<const CprSpan*> spans;
  for (const CprSpan& span : layout.spans)
    if (span.row == row) spans.push_back(&span);
  return spans;
}

double curveLengthPixels(const CprCurve& curve) {
  double length = 0;
  for (std::size_t n = 0; n + 1 < curve.pixels.size(); ++n)
    length += glm::distance(curve.pixels[n], curve.pixels[n + 1]);
  return length;
}

// --- Straightened -------------------------------------------------------------------------------

// Checks rows `margin` pixels away from both ends: one bright run, centred on the centre column
// (within half a pixel), as wide as the tube (within a pixel).
void expectStraightBand(const Cpr& cpr, double radiusMm, int centreColumn, int margin) {
  const double D = cpr.layout.pixelMm;
  int checked = 0;
  for (int y = margin; y < cpr.layout.height - margin; ++y) {
    const auto [first, last] = brightRun(cpr, y, 200.f);
    ASSERT_GE(first, 0) << "row " << y;
    // The 50 % level between samples: interpolate the edges to sub-pixel precision.
    auto edge = [&](int inside, int outside) {
      const float a = cpr.huAt(inside, y), b = cpr.huAt(outside, y);
      return inside + (outside - inside) * double(a - 200.f) / double(a - b);
    };
    const double left = edge(first, first - 1), right = edge(last, last + 1);
    EXPECT_NEAR((right - left) * D, 2 * radiusMm, D) << "row " << y;
    EXPECT_NEAR(0.5 * (left + right), centreColumn, 0.5) << "row " << y;
    for (int x = first; x <= last; ++x) ASSERT_GT(cpr.huAt(x, y), 200.f) << "gap in row " << y;
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

TEST(CprStraightened, ObliqueStraightTubeIsAStraightBandOfItsWidth) {
  const CenterlinePath path = straightPath({22, 25, 8}, {40, 36, 90});
  const Volume volume = tubeVolume({64, 64, 100}, glm::dvec3(1.0), {path}, 5.0);
  for (double angle : {0.0, 37.0, 90.0, 200.0}) {
    const ViewGeometry view = cprView(volume, Axis::k, angle, 0.5);
    const Cpr cpr = computeCpr(volume, {path}, view, {CprMode::straightened, 30.0});
    ASSERT_EQ(cpr.layout.width, 61);
    expectStraightBand(cpr, 5.0, 30, 16);
  }
}

TEST(CprStraightened, CurvedTubeIsAStraightBandToo) {
  // A quarter circle of radius 35 mm in the i-k plane, drifting along j: a curve in 3-D.
  const CenterlinePath path = polyline(
      "arc",
      [](double t) {
        const double a = 0.5 * kPi * t;
        return glm::dvec3(10 + 35 * (1 - std::cos(a)), 20 + 15 * t, 8 + 35 * std::sin(a));
      },
      200, 4.0);
  const Volume volume = tubeVolume({60, 44, 52}, glm::dvec3(1.0), {path}, 4.0);
  for (double angle : {0.0, 60.0, 135.0, 270.0}) {
    const Cpr cpr =
        computeCpr(volume, {path}, cprView(volume, Axis::k, angle, 0.5), {CprMode::straightened, 24.0});
    expectStraightBand(cpr, 4.0, cpr.layout.width / 2, 16);
  }
}

TEST(CprStraightened, RowsAreArcLengthAndTheCentreColumnIsTheCenterline) {
  const CenterlinePath path = polyline(
      "wave", [](double t) { return glm::dvec3(30 + 8 * std::sin(6 * t), 30, 5 + 80 * t); }, 120, 3);
  const Volume volume = emptyVolume();
  const ViewGeometry view = cprView(volume, Axis::k, 20, 0.5);
  const CprLayout layout = layoutCpr({path}, view, {CprMode::straightened, 20.0});
  const double length = pathLengthMm(path);
  EXPECT_EQ(layout.height, int(std::ceil(length / 0.5)));
  EXPECT_EQ(layout.width, 41);
  ASSERT_EQ(int(layout.spans.size()), layout.height);
  for (const CprSpan& span : layout.spans) {
    EXPECT_DOUBLE_EQ(span.arcMm, std::min((span.row + 0.5) * 0.5, length));
    EXPECT_EQ(span.centreX, 20);
    EXPECT_LT(distanceToPath(span.pointMm(20), path), 1e-9);
    EXPECT_NEAR(glm::length(span.stepMm), 0.5, 1e-12);
  }
}

TEST(CprStraightened, VectorOfInterestIsTheViewsRightForAVesselAlongTheUpAxis) {
  const Volume volume = emptyVolume();
  for (const auto& [from, to] : {std::pair{glm::dvec3(30, 30, 5), glm::dvec3(30, 30, 95)},
                                 std::pair{glm::dvec3(30, 30, 95), glm::dvec3(30, 30, 5)}}) {
    for (double angle : {0.0, 30.0, 90.0, 225.0}) {
      const ViewGeometry view = cprView(volume, Axis::k, angle, 1.0);
      const CprLayout layout = layoutCpr({straightPath(from, to)}, view, {CprMode::straightened, {}});
      for (const CprSpan& span : layout.spans) {
        EXPECT_LT(glm::distance(span.stepMm, view.right), 1e-9) << "angle " << angle;
      }
    }
  }
}

TEST(CprStraightened, RotatingTheViewRotatesAnEccentricPlaqueAroundTheLumen) {
  // A vertical tube with a calcified plaque on its +i wall (the view's right at angle 0).
  const CenterlinePath path = straightPath({30, 30, 5}, {30, 30, 95});
  Volume volume = tubeVolume({60, 60, 100}, glm::dvec3(1.0), {path}, 5.0);
  for (int k = 45; k <= 55; ++k)
    for (int j = 29; j <= 31; ++j)
      for (int i = 34; i <= 36; ++i) volume.voxels[volume.indexOf(i, j, k)] = encodeVoxel(1500);
  auto plaqueSide = [&](double angle) {
    const Cpr cpr =
        computeCpr(volume, {path}, cprView(volume, Axis::k, angle, 0.5), {CprMode::straightened, 30.0});
    float left = 0, right = 0;
    for (int y = 0; y < cpr.layout.height; ++y)
      for (int x = 0; x < cpr.layout.width; ++x) {
        float& side = x < 30 ? left : right;
        side = std::max(side, cpr.huAt(x, y));
      }
    return std::pair{left, right};
  };
  const auto [left0, right0] = plaqueSide(0);
  EXPECT_GT(right0, 1000.f);
  EXPECT_LT(left0, 500.f);
  const auto [left90, right90] = plaqueSide(90);  // the plaque is now behind the CPR's plane
  EXPECT_LT(std::max(left90, right90), 500.f);
  const auto [left180, right180] = plaqueSide(180);
  EXPECT_GT(left180, 1000.f);
  EXPECT_LT(right180, 500.f);
}

TEST(CprFrame, RotationMinimizingNormalsKeepThePlaneNormalOfAPlanarCurve) {
  std::vector<glm::dvec3> points, tangents;
  for (int n = 0; n <= 200; ++n) {
    const double a = 3 * kPi * n / 200;  // a planar S-bend in the x-z plane
    points.push_back({20 * std::sin(a), 0, 10 * a});
    tangents.push_back(glm::normalize(glm::dvec3(20 * std::cos(a), 0, 10)));
  }
  // Started off the plane's normal, the normal keeps its angle to it (no twist about the curve).
  const std::vector<glm::dvec3> normals =
      rotationMinimizingNormals(points, tangents, glm::dvec3(2, 1, 0));
  const double startAngle = glm::dot(normals.front(), glm::dvec3(0, 1, 0));
  EXPECT_LT(startAngle, 0.9);
  for (const glm::dvec3& normal : normals) EXPECT_NEAR(glm::dot(normal, {0, 1, 0}), startAngle, 1e-9);
  // Started on the plane's normal, it stays there.
  for (const glm::dvec3& normal : rotationMinimizingNormals(points, tangents, {0, 1, 0})) {
    EXPECT_LT(glm::distance(normal, {0, 1, 0}), 1e-9);
  }
}

TEST(CprFrame, RotationMinimizingNormalsTurnAgainstTheTorsionOfAHelix) {
  // Against the Frenet frame (n, b) of a helix, an exact RMF turns at minus the torsion:
  // N = cos(phi) n + sin(phi) b with phi(s) = phi(0) - tau s (Bishop 1975).
  const double a = 20, b = 5, c = std::sqrt(a * a + b * b), tau = b / (c * c);
  const int steps = 2000;
  std::vector<glm::dvec3> points, tangents, frenetN, frenetB;
  for (int n = 0; n <= steps; ++n) {
    const double t = 4 * kPi * n / steps;
    points.push_back({a * std::cos(t), a * std::sin(t), b * t});
    tangents.push_back(glm::dvec3(-a * std::sin(t), a * std::cos(t), b) / c);
    frenetN.push_back({-std::cos(t), -std::sin(t), 0});
    frenetB.push_back(glm::dvec3(b * std::sin(t), -b * std::cos(t), a) / c);
  }
  const std::vector<glm::dvec3> normals = rotationMinimizingNormals(points, tangents, {0, 0, 1});
  auto angle = [&](int n) {
    return std::atan2(glm::dot(normals[n], frenetB[n]), glm::dot(normals[n], frenetN[n]));
  };
  for (int n = 0; n <= steps; ++n) {
    EXPECT_NEAR(glm::dot(normals[n], tangents[n]), 0.0, 1e-12);
    const double s = c * 4 * kPi * n / steps;
    const double expected = angle(0) - tau * s;
    EXPECT_NEAR(std::remainder(angle(n) - expected, 2 * kPi), 0.0, 1e-4) << "step " << n;
  }
  // Two turns of the helix: the Frenet normal has spun by tau * length = 0.93 rad meanwhile.
  EXPECT_GT(tau * c * 4 * kPi, 0.9);
}

// --- Stretched ----------------------------------------------------------------------------------

TEST(CprStretched, HeightIsArcLengthOverPixelForAPathNormalToTheViewsRight) {
  // Axis k, angle 0: r = +i. The path bends in the j-k plane only.
  const CenterlinePath path = polyline(
      "bend", [](double t) { return glm::dvec3(30, 30 + 15 * std::sin(3 * t), 5 + 85 * t); }, 150, 3);
  const Volume volume = emptyVolume();
  for (double pixel : {0.5, 0.7, 1.3}) {
    const CprLayout layout =
        layoutCpr({path}, cprView(volume, Axis::k, 0, pixel), {CprMode::stretched, {}});
    EXPECT_EQ(layout.height, int(std::ceil(pathLengthMm(path) / pixel - 1e-9))) << pixel;
  }
}

TEST(CprStretched, IsIsometricAlongTheCenterlineAndKeepsTheDvrColumns) {
  // A path with a component along r: rows advance by the length normal to r only, and the
  // centerline drawn in the image keeps its true length.
  const CenterlinePath path = polyline(
      "sweep", [](double t) { return glm::dvec3(10 + 40 * t, 20 + 10 * std::sin(4 * t), 5 + 80 * t); },
      300, 3);
  const Volume volume = emptyVolume();
  const ViewGeometry view = cprView(volume, Axis::k, 0, 0.5);
  const CprLayout layout = layoutCpr({path}, view, {CprMode::stretched, 20.0});
  ASSERT_EQ(layout.curves.size(), 1u);
  EXPECT_NEAR(curveLengthPixels(layout.curves[0]) * 0.5, pathLengthMm(path), 1e-6);
  EXPECT_LT(layout.height, int(std::ceil(pathLengthMm(path) / 0.5)));
  for (const CprSpan& span : layout.spans) {
    // The crossing is on the centerline, in the DVR image's column of that point.
    const glm::dvec3 centre = span.originMm + span.centreX * span.stepMm;
    EXPECT_LT(distanceToPath(centre, path), 1e-9);
    const double dvrColumn =
        glm::dot(centre - view.centre, view.right) / view.pixelMm + 0.5 * view.width - 0.5;
    EXPECT_NEAR(span.centreX + layout.columnOffset, dvrColumn, 1e-9);
    EXPECT_LT(glm::distance(span.stepMm, 0.5 * view.right), 1e-12);  // rows along r
  }
}

// --- Projected ----------------------------------------------------------------------------------

struct SmallPhantom {
  Volume volume;
  std::vector<CenterlinePath> paths;  // volume frame
};

const SmallPhantom& smallPhantom() {
  static const SmallPhantom phantom = [] {
    PhantomOptions options;
    options.style = PhantomStyle::simple;
    options.dims = {128, 128, 300};
    Phantom generated = generatePhantom(options);
    SmallPhantom small;
    small.paths = toVolumeFrame(generated.centerlines, generated.volume).paths;
    small.volume = std::move(generated.volume);
    return small;
  }();
  return phantom;
}

TEST(CprProjected, CenterlinePixelLiesOnTheDvrImagesProjectedCenterlineAtEightAngles) {
  const SmallPhantom& phantom = smallPhantom();
  for (int n = 0; n < 8; ++n) {
    const double angle = 45.0 * n;
    RenderParams params;  // the DVR's view at the "medium" isd
    params.angleDeg = angle;
    const ViewGeometry view = makeViewGeometry(phantom.volume, params);
    const CprLayout layout = layoutCpr(phantom.paths, view, {CprMode::projected, {}});
    ASSERT_EQ(layout.width, view.width);
    ASSERT_EQ(layout.height, view.height);
    // The DVR image's projected centerline: every path densely sampled, projected with the view
    // (bucketed by the nearest row).
    std::vector<std::vector<glm::dvec2>> projected(view.height + 2);
    for (const CenterlinePath& path : phantom.paths) {
      for (const CenterlinePoint& point : resampleByArcLength(path, 0.05).points) {
        const glm::dvec3 q = point.positionMm - view.centre;
        const glm::dvec2 pixel{glm::dot(q, view.right) / view.pixelMm + 0.5 * view.width - 0.5,
                               0.5 * view.height - 0.5 - glm::dot(q, view.up) / view.pixelMm};
        const int row = int(std::floor(pixel.y + 0.5));
        if (row >= -1 && row <= view.height) projected[row + 1].push_back(pixel);
      }
    }
    int checked = 0;
    for (const CprSpan& span : layout.spans) {
      // The CPR's centerline pixel: of the row's columns near the crossing, the one whose sample
      // is nearest to the vessel's centerline in 3-D (the path near the crossing's arc length).
      const CenterlinePath nearby = pathPiece(phantom.paths[span.path], span.arcMm, 20);
      int best = -1;
      double bestDistance = std::numeric_limits<double>::max();
      for (int x = std::max(span.x0, int(span.centreX) - 3);
           x < std::min(span.x1, int(span.centreX) + 5); ++x) {
        const double distance = distanceToPath(span.pointMm(x), nearby);
        if (distance < bestDistance) bestDistance = distance, best = x;
      }
      if (best < 0) continue;  // clipped at the volume's border
      EXPECT_LE(bestDistance, view.pixelMm) << "angle " << angle << " row " << span.row;
      double nearest = std::numeric_limits<double>::max();
      for (int row = span.row - 1; row <= span.row + 1; ++row) {
        for (glm::dvec2 p : projected[row + 1]) {
          nearest = std::min(nearest, glm::distance(p, glm::dvec2(best, span.row)));
        }
      }
      EXPECT_LE(nearest, 1.0) << "angle " << angle << " row " << span.row;
      // Registration: every pixel's sample lies on that pixel's DVR ray.
      for (int x : {span.x0, best, span.x1 - 1}) {
        const glm::dvec3 offset = span.pointMm(x) - view.rayOrigin(x, span.row);
        EXPECT_LT(glm::length(glm::cross(offset, view.viewDir)), 1e-6);
      }
      ++checked;
    }
    EXPECT_GT(checked, view.height / 2) << "angle " << angle;
  }
}

TEST(CprProjected, RowsCrossedTwiceAreSplitAtTheMidpointAndBandsLimitTheWidth) {
  // A U-turn in the i-k plane: rows between its ends are crossed twice.
  const CenterlinePath path = polyline(
      "u",
      [](double t) { return glm::dvec3(30 + 15 * std::cos(kPi * t), 30, 70 - 40 * std::sin(kPi * t)); },
      200, 2);
  const Volume volume = emptyVolume();
  const ViewGeometry view = cprView(volume, Axis::k, 0, 1.0);
  const CprLayout whole = layoutCpr({path}, view, {CprMode::projected, {}});
  const CprLayout band = layoutCpr({path}, view, {CprMode::projected, 6.0});
  const int row = int(std::lround(0.5 * view.height - 0.5 - (50 - view.centre.z)));  // z = 50
  const std::vector<const CprSpan*> spans = spansOfRow(whole, row);
  ASSERT_EQ(spans.size(), 2u);
  const double middle = 0.5 * (spans[0]->centreX + spans[1]->centreX);
  EXPECT_EQ(spans[0]->x1, int(std::floor(middle)) + 1);
  EXPECT_EQ(spans[1]->x0, spans[0]->x1);
  for (const CprSpan* span : spansOfRow(band, row)) {
    EXPECT_LE(span->x1 - span->x0, 7);
    EXPECT_GE(span->x0, span->centreX - 3);
    EXPECT_LE(span->x1 - 1, span->centreX + 3);
  }
}

// --- Several paths ------------------------------------------------------------------------------

// A "Y": a trunk along k, then two branches to either side in i.
std::vector<CenterlinePath> yTree() {
  auto branch = [](double side) {
    return polyline(
        side < 0 ? "left" : "right",
        [side](double t) {
          const double s = 100 * t;  // mm along: 40 mm trunk, then a smooth turn outwards
          const double out = s <= 40 ? 0 : side * 0.006 * (s - 40) * (s - 40);
          return glm::dvec3(40 + out, 30, 95 - 0.85 * s);
        },
        101, 3);
  };
  return {branch(-1), branch(+1)};
}

TEST(CprMultiPath, StraightenedPanelsShareTheTrunkRows) {
  const std::vector<CenterlinePath> tree = yTree();
  const double trunkArc = arcLengthsMm(tree[0])[sharedPrefixLength(tree[0], tree[1]) - 1];
  const Volume volume = tubeVolume({80, 60, 100}, glm::dvec3(1.0), tree, 3.0);
  const ViewGeometry view = cprView(volume, Axis::k, 10, 0.5);
  const Cpr both = computeCpr(volume, tree, view, {CprMode::straightened, 20.0});
  const Cpr first = computeCpr(volume, {tree[0]}, view, {CprMode::straightened, 20.0});
  const int panel = first.layout.width;
  ASSERT_EQ(panel, 41);
  ASSERT_EQ(both.layout.width, 2 * panel);
  for (int y = 0; y < both.layout.height; ++y) {
    const std::vector<const CprSpan*> spans = spansOfRow(both.layout, y);
    if ((y + 0.5) * 0.5 <= trunkArc) {
      ASSERT_EQ(spans.size(), 1u) << "row " << y;
      EXPECT_EQ(spans[0]->centreX, panel - 1);
      // The trunk row shows what the single path's CPR shows, shifted to the shared centre.
      for (int dx = -20; dx <= 20; ++dx) {
        EXPECT_NEAR(both.huAt(panel - 1 + dx, y), first.huAt(20 + dx, y), 1e-3) << "row " << y;
      }
    } else {
      ASSERT_EQ(spans.size(), 2u) << "row " << y;
      EXPECT_EQ(spans[0]->centreX, 20);
      EXPECT_EQ(spans[1]->centreX, panel + 20);
      EXPECT_GT(both.huAt(panel + 20, y), 200.f) << "right branch lumen, row " << y;
    }
  }
  // Path 1's marker starts where it leaves the trunk, at the trunk's centre.
  ASSERT_EQ(both.layout.curves.size(), 2u);
  EXPECT_NEAR(both.layout.curves[1].arcMm.front(), trunkArc, 0.5);
  EXPECT_EQ(both.layout.curves[1].pixels.front().x, panel - 1);
}

TEST(CprMultiPath, StretchedAndProjectedDrawTheTrunkOnce) {
  const std::vector<CenterlinePath> tree = yTree();
  const double trunkArc = arcLengthsMm(tree[0])[sharedPrefixLength(tree[0], tree[1]) - 1];
  const Volume volume = emptyVolume({80, 60, 100});
  const ViewGeometry view = cprView(volume, Axis::k, 0, 0.5);
  for (CprMode mode : {CprMode::stretched, CprMode::projected}) {
    const CprLayout layout = layoutCpr(tree, view, {mode, {}});
    int trunkRows = 0, branchRows = 0;
    for (int y = 0; y < layout.height; ++y) {
      const std::vector<const CprSpan*> spans = spansOfRow(layout, y);
      if (spans.empty()) continue;
      const double arc = spans[0]->arcMm;
      if (arc < trunkArc - 1) {
        EXPECT_EQ(spans.size(), 1u) << toString(mode) << " row " << y;
        ++trunkRows;
      } else if (arc > trunkArc + 3) {
        EXPECT_EQ(spans.size(), 2u) << toString(mode) << " row " << y;
        ++branchRows;
      }
    }
    EXPECT_GT(trunkRows, 60) << toString(mode);
    EXPECT_GT(branchRows, 60) << toString(mode);
  }
}

// --- Resampling ---------------------------------------------------------------------------------

struct Aorta {
  Volume volume;
  Centerlines centerlines;  // volume frame
};

const Aorta& aorta() {
  static const Aorta data = [] {
    Aorta a;
    a.volume = readVolume(ANGIORAY_SHARED_DATA "/aorta.mha").volume;
    a.centerlines =
        toVolumeFrame(loadCenterlines(ANGIORAY_SHARED_DATA "/aorta-centerlines.vtp"), a.volume);
    return a;
  }();
  return data;
}

// Trilinear interpolation written out from the textbook formula (independent of
// core/volume_sampling.h): the 8 corners of the cell around q, weighted by the opposite volumes.
double referenceTrilinearHu(const Volume& volume, glm::dvec3 q) {
  glm::ivec3 base;
  glm::dvec3 f;
  for (int axis = 0; axis < 3; ++axis) {
    const double clamped = std::clamp(q[axis], 0.0, volume.dims[axis] - 1.0);
    base[axis] = std::min(int(clamped), std::max(volume.dims[axis] - 2, 0));
    f[axis] = clamped - base[axis];
  }
  double sum = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::ivec3 d{corner & 1, corner >> 1 & 1, corner >> 2};
    const glm::ivec3 v = glm::min(base + d, volume.dims - 1);
    const double weight = (d.x ? f.x : 1 - f.x) * (d.y ? f.y : 1 - f.y) * (d.z ? f.z : 1 - f.z);
    sum += weight * volume.densityAt(v.x, v.y, v.z);
  }
  return sum - kHuOffset;
}

// Largest |CPR - trilinear reference| over all sampled pixels; also checks that exactly the span
// pixels are sampled.
struct Deviation {
  double max = 0;
  double mean = 0;
  double overOneHu = 0;  // fraction of pixels
  long pixels = 0;
};

Deviation deviationFromTrilinear(const Volume& volume, const Cpr& cpr,
                                 double (*bound)(const Volume&, glm::dvec3) = nullptr) {
  Deviation d;
  std::vector<char> covered(cpr.hu.size(), 0);
  double sum = 0;
  long over = 0;
  for (const CprSpan& span : cpr.layout.spans) {
    for (int x = span.x0; x < span.x1; ++x) {
      const glm::dvec3 q = span.pointMm(x) / volume.spacing;
      const double reference = referenceTrilinearHu(volume, q);
      const double error = std::abs(cpr.huAt(x, span.row) - reference);
      if (bound) {
        EXPECT_LE(error, bound(volume, q) + 0.01) << "q " << q.x << " " << q.y << " " << q.z;
      }
      d.max = std::max(d.max, error);
      sum += error;
      over += error > 1.0;
      covered[std::size_t(span.row) * cpr.layout.width + x] = 1;
      ++d.pixels;
    }
  }
  for (std::size_t n = 0; n < covered.size(); ++n) EXPECT_EQ(!covered[n], std::isnan(cpr.hu[n]));
  d.mean = d.pixels ? sum / d.pixels : 0;
  d.overOneHu = d.pixels ? double(over) / d.pixels : 0;
  return d;
}

// cv::remap's known error: the position in the cell is rounded to 1/32 voxel (1/64 at most), so
// the bilinear value is off by at most 1/64 of the cell's spread along i plus along j.
double remapQuantisationBound(const Volume& volume, glm::dvec3 q) {
  const Cell cell = cellAt(volume, q);
  float lo = 1e9f, hi = -1e9f;
  for (int c = 0; c < 8; ++c) {
    const float d = densityAtClamped(volume, cell.base + glm::ivec3(c & 1, c >> 1 & 1, c >> 2));
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return 2.0 * (hi - lo) / 64.0;
}

TEST(CprResampling, ValuesAreTheTrilinearReferenceAndTheRemapIsMeasured) {
  const Aorta& data = aorta();
  for (CprMode mode : {CprMode::projected, CprMode::stretched, CprMode::straightened}) {
    const ViewGeometry view = cprView(data.volume, Axis::j, 30, 0.5);
    const CprSettings settings{mode, {}};
    const Cpr exact = computeCpr(data.volume, data.centerlines.paths, view, settings);
    const Deviation trilinear = deviationFromTrilinear(data.volume, exact);
    EXPECT_GT(trilinear.pixels, 10000);
    EXPECT_LE(trilinear.max, 0.01) << toString(mode);  // exact up to float rounding

    const Cpr remapped =
        computeCpr(data.volume, data.centerlines.paths, view, settings, CprResampler::opencvRemap);
    const Deviation remap = deviationFromTrilinear(data.volume, remapped, remapQuantisationBound);
    std::printf(
        "[ measure  ] %s CPR of the aorta, %ld pixels: cv::remap vs trilinear: max %.2f HU, "
        "mean %.3f HU, %.2f %% of pixels off by more than 1 HU\n",
        toString(mode), remap.pixels, remap.max, remap.mean, 100 * remap.overOneHu);
    EXPECT_LT(remap.mean, 1.0);
  }
}

// --- The aorta ----------------------------------------------------------------------------------

TEST(CprAorta, StraightenedCentreColumnIsContrastLumen) {
  // aorta.mha is not calibrated in HU (shared data README). Its lumen stays brighter than every
  // tissue voxel, also at the trunk's start where the contrast fades, so one threshold between the
  // brightest tissue and the faintest lumen tells them apart.
  constexpr float kLumenThreshold = 800.f;
  const Aorta& data = aorta();
  ASSERT_EQ(data.centerlines.paths.size(), 2u);
  for (std::size_t p = 0; p < 2; ++p) {
    for (double angle : {0.0, 90.0}) {
      const ViewGeometry view = cprView(data.volume, Axis::j, angle, 0.5);
      const Cpr cpr =
          computeCpr(data.volume, {data.centerlines.paths[p]}, view, {CprMode::straightened, {}});
      const int centre = cpr.layout.width / 2;
      int lumen = 0;
      for (int y = 0; y < cpr.layout.height; ++y) lumen += cpr.huAt(centre, y) > kLumenThreshold;
      const double fraction = double(lumen) / cpr.layout.height;
      std::printf("[ measure  ] aorta path %zu, angle %.0f: %.1f %% of %d centre pixels > %.0f\n", p,
                  angle, 100 * fraction, cpr.layout.height, kLumenThreshold);
      EXPECT_GE(fraction, 0.95) << "path " << p;
    }
  }
}

TEST(CprPick, PixelsGiveTheirPointHuAndArcLength) {
  const std::vector<CenterlinePath> tree = yTree();
  const Volume volume = tubeVolume({80, 60, 100}, glm::dvec3(1.0), tree, 3.0);
  const Cpr cpr =
      computeCpr(volume, tree, cprView(volume, Axis::k, 0, 0.5), {CprMode::straightened, 20.0});
  const int lastRow = cpr.layout.height - 1;
  const std::optional<CprPick> right = pickCpr(cpr, 41 + 20, lastRow);  // the right branch's end
  ASSERT_TRUE(right);
  EXPECT_EQ(right->path, 1);
  EXPECT_NEAR(right->arcMm, pathLengthMm(tree[1]), 0.5);
  EXPECT_LT(glm::distance(right->pointMm, tree[1].points.back().positionMm), 0.5);
  EXPECT_EQ(right->hu, cpr.huAt(61, lastRow));
  const std::optional<CprPick> trunk = pickCpr(cpr, 3, 10);
  ASSERT_TRUE(trunk);
  EXPECT_EQ(trunk->path, 0);
  EXPECT_DOUBLE_EQ(trunk->arcMm, 10.5 * 0.5);
  EXPECT_FALSE(pickCpr(cpr, -1, 10));
  EXPECT_FALSE(pickCpr(cpr, 0, cpr.layout.height));
}

// --- Display and metadata -----------------------------------------------------------------------

TEST(CprDisplay, WindowLevelGreyTransparentGapsAndTfColor) {
  EXPECT_FLOAT_EQ(windowGrey(250, {800, 250}), 0.5f);
  EXPECT_FLOAT_EQ(windowGrey(-150, {800, 250}), 0.0f);
  EXPECT_FLOAT_EQ(windowGrey(450, {800, 250}), 0.75f);
  EXPECT_FLOAT_EQ(windowGrey(5000, {800, 250}), 1.0f);
  ASSERT_TRUE(windowPreset("calcium"));
  EXPECT_EQ(windowPreset("calcium")->window, kCalciumWindow.window);
  EXPECT_FALSE(windowPreset("bone"));

  const CenterlinePath path = straightPath({30, 30, 5}, {30, 30, 95});
  const Volume volume = tubeVolume({60, 60, 100}, glm::dvec3(1.0), {path}, 5.0);
  // Wider than the volume: the outer columns are not sampled.
  const Cpr cpr =
      computeCpr(volume, {path}, cprView(volume, Axis::k, 0, 1.0), {CprMode::straightened, 80.0});
  CprDisplay plain;
  plain.centerlineMarker = plain.ruler = false;
  const Image grey = displayCpr(cpr.layout, cpr.hu, plain);
  for (int y = 0; y < cpr.layout.height; ++y)
    for (int x = 0; x < cpr.layout.width; ++x) {
      const float hu = cpr.huAt(x, y);
      const glm::vec4 pixel = grey.at(x, y);
      if (std::isnan(hu)) {
        EXPECT_EQ(pixel, glm::vec4(0.f));
      } else {
        EXPECT_EQ(pixel, glm::vec4(glm::vec3(windowGrey(hu, plain.windowLevel)), 1.f));
      }
    }
  EXPECT_TRUE(std::isnan(cpr.huAt(0, 50)));

  TransferFunction tf;
  tf.points = {{-1024, {0, 0, 1}, 0}, {1000, {1, 0, 0}, 1}};
  plain.tf = tf;
  const Image colored = displayCpr(cpr.layout, cpr.hu, plain);
  const int centre = cpr.layout.width / 2;
  const glm::vec4 lumen = colored.at(centre, 50);
  const glm::vec3 expected(buildTable(tf).rgba[densityOfHu(cpr.huAt(centre, 50))]);
  EXPECT_EQ(glm::vec3(lumen), expected);
  EXPECT_EQ(lumen.a, 1.f);
}

TEST(CprDisplay, MarkerAndRulerDrawOnTheCenterlineOnly) {
  const CenterlinePath path = straightPath({30, 30, 5}, {30, 30, 95});
  const Volume volume = emptyVolume();
  const Cpr cpr =
      computeCpr(volume, {path}, cprView(volume, Axis::k, 0, 0.5), {CprMode::straightened, 40.0});
  CprDisplay plain;
  plain.centerlineMarker = plain.ruler = false;
  CprDisplay marked;
  marked.ruler = false;
  const Image without = displayCpr(cpr.layout, cpr.hu, plain);
  const Image with = displayCpr(cpr.layout, cpr.hu, marked);
  const int centre = cpr.layout.width / 2;
  int changed = 0;
  for (int y = 0; y < with.height; ++y)
    for (int x = 0; x < with.width; ++x) {
      if (with.at(x, y) == without.at(x, y)) continue;
      EXPECT_EQ(x, centre) << "row " << y;
      ++changed;
    }
  // Dashed (6 pixels on, 3 off, give or take the pixels a dash's end touches), not solid.
  EXPECT_GT(double(changed) / with.height, 0.55);
  EXPECT_LT(double(changed) / with.height, 0.85);

  CprDisplay ruled = plain;
  ruled.ruler = true;
  const Image ruler = displayCpr(cpr.layout, cpr.hu, ruled);
  // A tick across the centre line every 10 mm = 20 rows: row of s = 50 mm is (50 / 0.5 - 0.5).
  const int tickRow = int(std::lround(50 / 0.5 - 0.5));
  EXPECT_NE(ruler.at(centre + 5, tickRow), without.at(centre + 5, tickRow));
  EXPECT_EQ(ruler.at(centre + 5, tickRow + 10), without.at(centre + 5, tickRow + 10));
}

TEST(CprMetadata, SaysHowToMeasure) {
  const Volume volume = emptyVolume();
  const CprLayout layout = layoutCpr({straightPath({30, 30, 5}, {30, 30, 95})},
                                     cprView(volume, Axis::k, 15, 0.5), {CprMode::straightened, {}});
  CprDescription description;
  description.pathNames = {"left", "right"};
  description.angleDeg = 15;
  const auto metadata = cprMetadata(layout, description);
  EXPECT_EQ(metadata.at("cpr_mode"), "straightened");
  EXPECT_EQ(metadata.at("mm_per_pixel"), "0.5");
  EXPECT_EQ(metadata.at("angle_deg"), "15");
  EXPECT_EQ(metadata.at("cpr_paths"), "left; right");
  EXPECT_NE(metadata.at("cpr_rows").find("arc length"), std::string::npos);
}

// --- Errors -------------------------------------------------------------------------------------

std::string errorOf(const std::function<void()>& work) {
  try {
    work();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(CprErrors, BadPathSelectionsNameTheIndexAndTheRange) {
  Centerlines centerlines;
  centerlines.paths = {straightPath({1, 1, 1}, {1, 1, 9}), straightPath({2, 1, 1}, {2, 1, 9})};
  EXPECT_EQ(selectPaths(centerlines, "all").size(), 2u);
  EXPECT_EQ(selectPaths(centerlines, "1").size(), 1u);
  EXPECT_EQ(errorOf([&] { selectPaths(centerlines, "2"); }), "there is no path 2; it has 2 (0..1)");
  EXPECT_EQ(errorOf([&] { selectPaths(centerlines, "-1"); }), "there is no path -1; it has 2 (0..1)");
  EXPECT_NE(errorOf([&] { selectPaths(centerlines, "1x"); }).find("neither 'all' nor"),
            std::string::npos);
}

TEST(CprErrors, EmptyDegenerateAndOutsidePathsAreRefusedWithTheirName) {
  const Volume volume = emptyVolume();
  const ViewGeometry view = cprView(volume, Axis::k, 0, 1.0);
  auto layoutOf = [&](CenterlinePath path, CprSettings settings = {}) {
    return errorOf([&] { layoutCpr({path}, view, settings); });
  };
  EXPECT_EQ(layoutOf({"empty", {}}), "path 'empty' has no points");
  EXPECT_EQ(layoutOf({"dot", {{{5, 5, 5}, 1}}}),
            "path 'dot' has a single point; a CPR needs at least 2");
  EXPECT_EQ(layoutOf({"still", {{{5, 5, 5}, 1}, {{5, 5, 5}, 1}}}), "path 'still' has zero length");
  EXPECT_EQ(layoutOf({"nan", {{{5, 5, 5}, 1}, {{5, NAN, 5}, 1}}}),
            "path 'nan' has a non-finite coordinate");
  CenterlinePath away = straightPath({100, 100, 5}, {100, 100, 90});
  away.name = "away";
  EXPECT_EQ(layoutOf(away), "path 'away' lies entirely outside the volume");
  EXPECT_EQ(errorOf([&] { layoutCpr({}, view, {}); }), "no centerline paths to reformat");
  EXPECT_NE(
      layoutOf(straightPath({30, 30, 5}, {30, 30, 95}), {CprMode::straightened, -3.0}).find("width"),
      std::string::npos);
  EXPECT_NE(errorOf([&] { cprView(volume, Axis::k, 0, 0.0); }).find("pixel size"), std::string::npos);
  EXPECT_NE(
      errorOf([&] { cprView(volume, Axis::k, 0, 1e-9); }).find("too small for this volume (at least"),
      std::string::npos);
  // Problems of the paths (the CLI blames the centerline file) are told apart from the others.
  EXPECT_THROW(layoutCpr({CenterlinePath{"empty", {}}}, view, {}), CprPathError);
  bool pathError = false;
  try {
    layoutCpr({straightPath({30, 30, 5}, {30, 30, 95})}, view, {CprMode::straightened, -3.0});
  } catch (const CprPathError&) {
    pathError = true;
  } catch (const std::invalid_argument&) {
  }
  EXPECT_FALSE(pathError);
  EXPECT_NE(errorOf([&] {
              layoutCpr({straightPath({30, 30, 5}, {30, 30, 95})}, cprView(volume, Axis::k, 0, 1e-3),
                        {CprMode::straightened, {}});
            }).find("pixels; choose a larger pixel size"),
            std::string::npos);
}

TEST(CprErrors, PathLeavingTheVolumeIsClippedWithAWarning) {
  // Half of this path runs above the volume's top (z > 99).
  CenterlinePath path = straightPath({30, 30, 50}, {30, 30, 150}, 101);
  path.name = "escaping";
  const Volume volume = tubeVolume({60, 60, 100}, glm::dvec3(1.0), {path}, 4.0);
  for (CprMode mode : {CprMode::projected, CprMode::stretched, CprMode::straightened}) {
    const Cpr cpr = computeCpr(volume, {path}, cprView(volume, Axis::k, 0, 1.0), {mode, {}});
    ASSERT_EQ(cpr.layout.warnings.size(), 1u) << toString(mode);
    EXPECT_EQ(cpr.layout.warnings[0],
              "path 'escaping': 51 of 101 points lie outside the volume; the CPR is clipped there");
    // What is sampled lies inside the volume and is the tube's lumen at the centre.
    long sampled = 0;
    for (const CprSpan& span : cpr.layout.spans) {
      for (int x : {span.x0, span.x1 - 1}) {
        const glm::dvec3 p = span.pointMm(x);
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, glm::dvec3(-1e-6))) &&
                    glm::all(glm::lessThanEqual(p, domainExtent(volume) + 1e-6)));
      }
      sampled += span.x1 - span.x0;
    }
    EXPECT_GT(sampled, 0) << toString(mode);
  }
}

}  // namespace
}  // namespace angio
