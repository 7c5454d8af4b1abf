#include "phantom/phantom_arteries.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace angio::phantom {

namespace {

// A sinusoidal wiggle across the branch between two heights, faded in and out (sin^2 window) so
// the curve stays smooth: a tortuous segment. It swings along x (left-right) made perpendicular to
// the branch, so that it shows in frontal views.
struct Wiggle {
  double fromHeightMm = 0;
  double toHeightMm = 0;
  double amplitudeMm = 0;
  double wavelengthMm = 0;
};

// The radius narrowed to residualFraction over lengthMm (including cosine ramps of rampMm).
struct Stenosis {
  double atHeightMm = 0;
  double lengthMm = 0;
  double rampMm = 0;
  double residualFraction = 1;
};

// A calcified plaque on the wall: where along the branch (fraction of its length), at which angle
// around it, how big.
struct PlaqueSpec {
  double atFraction = 0;
  double angleDeg = 0;
  double radiusMm = 0;
  double hu = 0;
};

struct BranchSpec {
  std::string name;
  int parent = -1;
  std::vector<CurvePoint> knots;  // a child's first knot is replaced by its parent's end
  std::vector<Wiggle> wiggles;
  std::vector<Stenosis> stenoses;
  std::vector<PlaqueSpec> plaques;
};

constexpr double kPi = std::numbers::pi;

BranchSpec branch(std::string name, int parent, std::vector<CurvePoint> knots) {
  BranchSpec spec;
  spec.name = std::move(name);
  spec.parent = parent;
  spec.knots = std::move(knots);
  return spec;
}

std::string sideName(double side) { return side > 0 ? "left" : "right"; }

CurvePoint knot(double x, double y, double z, double r) { return {{x, y, z}, r}; }

// side = +1 for the patient's left (x > 0), -1 for the right: anatomy is written for the left leg.
std::vector<CurvePoint> mirrored(std::vector<CurvePoint> knots, double side) {
  for (CurvePoint& k : knots) k.position.x *= side;
  return knots;
}

BranchSpec aorta() {
  // Anterior-left of the lumbar spine, bifurcating at L4.
  BranchSpec spec = branch("aorta", -1,
                           {knot(14, 6, 1195, 10.5), knot(14, 5, 1150, 10.0), knot(13, 3, 1100, 9.3),
                            knot(12, 4, 1058, 8.6)});
  spec.plaques = {{0.25, 40, 3.0, 1300}, {0.6, 200, 2.5, 1450}, {0.9, 300, 3.5, 1200}};
  return spec;
}

// Common iliac -> external iliac (tortuous) -> common and superficial femoral -> popliteal. The
// femoral passes behind the femur (adductor hiatus) into the popliteal fossa.
BranchSpec iliacToPopliteal(double side, int parent) {
  std::vector<CurvePoint> knots = mirrored(
      {knot(12, 4, 1058, 5.6), knot(32, 8, 1025, 5.4), knot(47, 14, 993, 5.1), knot(60, 6, 962, 4.9),
       knot(74, -14, 932, 4.7), knot(85, -34, 906, 4.6), knot(88, -38, 880, 4.5),
       knot(85, -27, 800, 4.3), knot(81, -8, 700, 4.0), knot(74, 12, 630, 3.8), knot(76, 64, 585, 3.7),
       knot(89, 82, 540, 3.6), knot(92, 89, 490, 3.4), knot(93, 86, 432, 3.2)},
      side);
  const bool left = side > 0;
  BranchSpec spec = branch(sideName(side) + "-iliac-femoral-popliteal", parent, knots);
  spec.wiggles.push_back({985, 915, left ? 3.0 : 5.0, 40});  // external iliac
  if (left) {
    spec.stenoses.push_back({700, 18, 4, 0.4});  // superficial femoral, mid-thigh
    spec.plaques = {
        {0.04, 90, 2.0, 1350}, {0.15, 250, 1.8, 1250}, {0.55, 45, 1.6, 1400}, {0.8, 160, 1.4, 1300}};
  } else {
    spec.wiggles.push_back({830, 730, 4.0, 30});  // a tortuous superficial femoral too
    spec.plaques = {{0.06, 270, 2.0, 1300}, {0.3, 120, 1.8, 1450}, {0.65, 300, 1.5, 1250}};
  }
  return spec;
}

// Leaves the popliteal forwards nearly horizontally through the interosseous membrane, runs down
// in front of it and, as the dorsalis pedis, crosses the top of the foot nearly horizontally.
BranchSpec anteriorTibial(double side, int parent) {
  return branch(sideName(side) + "-anterior-tibial", parent,
                mirrored({knot(93, 86, 432, 2.6), knot(99, 64, 427, 2.5), knot(106, 42, 422, 2.4),
                          knot(107, 27, 400, 2.3), knot(105, 24, 300, 2.1), knot(99, 17, 200, 1.9),
                          knot(91, 12, 130, 1.8), knot(88, 11, 90, 1.7), knot(88, 4, 72, 1.65),
                          knot(88, -15, 60, 1.6), knot(88, -45, 51, 1.55), knot(87, -75, 44, 1.5)},
                         side));
}

// Down the back of the calf, behind the medial malleolus, then forwards along the sole.
BranchSpec posteriorTibial(double side, int parent) {
  return branch(sideName(side) + "-posterior-tibial", parent,
                mirrored({knot(93, 86, 432, 2.8), knot(90, 83, 400, 2.7), knot(83, 76, 300, 2.4),
                          knot(77, 70, 200, 2.1), knot(72, 64, 120, 1.9), knot(65, 62, 85, 1.8),
                          knot(64, 52, 50, 1.7), knot(68, 30, 26, 1.6), knot(78, 0, 22, 1.55),
                          knot(82, -35, 18, 1.5)},
                         side));
}

std::vector<BranchSpec> branchSpecs() {
  std::vector<BranchSpec> specs{aorta()};
  for (double side : {1.0, -1.0}) {
    const int trunk = int(specs.size());
    specs.push_back(iliacToPopliteal(side, 0));
    specs.push_back(anteriorTibial(side, trunk));
    specs.push_back(posteriorTibial(side, trunk));
  }
  return specs;
}

// Arc length at which a descending curve first reaches the height (or its end).
double arcLengthAtHeight(const std::vector<CurvePoint>& curve, const std::vector<double>& lengths,
                         double heightMm) {
  for (std::size_t n = 0; n < curve.size(); ++n) {
    if (curve[n].position.z <= heightMm) return lengths[n];
  }
  return lengths.back();
}

glm::dvec3 tangentAt(const std::vector<CurvePoint>& curve, std::size_t n) {
  const std::size_t before = n == 0 ? 0 : n - 1;
  const std::size_t after = std::min(n + 1, curve.size() - 1);
  return glm::normalize(curve[after].position - curve[before].position);
}

void applyWiggle(std::vector<CurvePoint>& curve, const Wiggle& wiggle) {
  const std::vector<double> lengths = arcLengths(curve);
  const double s0 = arcLengthAtHeight(curve, lengths, wiggle.fromHeightMm);
  const double s1 = arcLengthAtHeight(curve, lengths, wiggle.toHeightMm);
  if (s1 <= s0) return;
  const std::vector<CurvePoint> straight = curve;
  for (std::size_t n = 0; n < curve.size(); ++n) {
    const double s = lengths[n];
    if (s <= s0 || s >= s1) continue;
    const double window = std::pow(std::sin(kPi * (s - s0) / (s1 - s0)), 2);
    const double offset =
        wiggle.amplitudeMm * window * std::sin(2 * kPi * (s - s0) / wiggle.wavelengthMm);
    const glm::dvec3 t = tangentAt(straight, n);
    const glm::dvec3 across = glm::normalize(glm::dvec3(1, 0, 0) - t.x * t);
    curve[n].position += offset * across;
  }
}

void applyStenosis(std::vector<CurvePoint>& curve, const Stenosis& stenosis) {
  const std::vector<double> lengths = arcLengths(curve);
  const double centre = arcLengthAtHeight(curve, lengths, stenosis.atHeightMm);
  const double plateau = stenosis.lengthMm / 2 - stenosis.rampMm;
  for (std::size_t n = 0; n < curve.size(); ++n) {
    const double d = std::abs(lengths[n] - centre);
    if (d >= stenosis.lengthMm / 2) continue;
    const double depth =
        d <= plateau ? 1.0 : 0.5 + 0.5 * std::cos(kPi * (d - plateau) / stenosis.rampMm);
    curve[n].radius *= 1.0 - (1.0 - stenosis.residualFraction) * depth;
  }
}

Plaque placePlaque(const std::vector<CurvePoint>& curve, const PlaqueSpec& spec) {
  const std::size_t n = std::min(curve.size() - 1, std::size_t(spec.atFraction * curve.size()));
  const glm::dvec3 t = tangentAt(curve, n);
  const glm::dvec3 n1 = perpendicular(t);
  const glm::dvec3 n2 = glm::cross(t, n1);
  const double angle = spec.angleDeg * kPi / 180;
  const glm::dvec3 outward = std::cos(angle) * n1 + std::sin(angle) * n2;
  // Centred just inside the wall: about half of the plaque narrows the lumen.
  return {curve[n].position + 0.95 * curve[n].radius * outward, spec.radiusMm, spec.hu};
}

constexpr double kFineStepMm = 0.5;   // before wiggles and stenoses are applied
constexpr double kPointStepMm = 1.0;  // the branch's final points

ArteryBranch buildBranch(const BranchSpec& spec, std::vector<Plaque>& plaques) {
  std::vector<CurvePoint> curve = resample(catmullRom(spec.knots, 32), kFineStepMm);
  for (const Wiggle& wiggle : spec.wiggles) applyWiggle(curve, wiggle);
  for (const Stenosis& stenosis : spec.stenoses) applyStenosis(curve, stenosis);
  curve = resample(curve, kPointStepMm);
  for (const PlaqueSpec& plaque : spec.plaques) plaques.push_back(placePlaque(curve, plaque));
  return {spec.name, spec.parent, std::move(curve)};
}

}  // namespace

ArterialTree buildArterialTree() {
  ArterialTree tree;
  for (BranchSpec spec : branchSpecs()) {
    if (spec.parent >= 0) {
      spec.knots.front().position = tree.branches[spec.parent].points.back().position;
    }
    tree.branches.push_back(buildBranch(spec, tree.plaques));
  }
  return tree;
}

std::vector<CenterlinePath> rootToLeafPaths(const ArterialTree& tree) {
  const int count = int(tree.branches.size());
  std::vector<bool> hasChild(count, false);
  for (const ArteryBranch& branch : tree.branches) {
    if (branch.parent >= 0) hasChild[branch.parent] = true;
  }
  std::vector<CenterlinePath> paths;
  for (int leaf = 0; leaf < count; ++leaf) {
    if (hasChild[leaf]) continue;
    std::vector<int> chain;
    for (int b = leaf; b >= 0; b = tree.branches[b].parent) chain.insert(chain.begin(), b);
    CenterlinePath path{"aorta-" + tree.branches[leaf].name, {}};
    for (int b : chain) {
      const auto& points = tree.branches[b].points;
      // A child's first point is its parent's last one.
      for (std::size_t n = path.points.empty() ? 0 : 1; n < points.size(); ++n) {
        path.points.push_back({points[n].position, points[n].radius});
      }
    }
    paths.push_back(std::move(path));
  }
  return paths;
}

}  // namespace angio::phantom
