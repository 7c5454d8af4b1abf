#include "phantom/phantom_anatomy.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include "core/labels.h"
#include "phantom/phantom_arteries.h"
#include "phantom/phantom_organs.h"

namespace angio::phantom {

namespace {

// Signed distance to the curved layer between radii inner and outer (mm) around centre, cut to
// |x| <= halfWidth.
double curvedLayerDistance(glm::dvec2 p, glm::dvec2 centre, double inner, double outer,
                           double halfWidth) {
  const double rho = glm::length(p - centre);
  return std::max({inner - rho, rho - outer, std::abs(p.x) - halfWidth});
}

}  // namespace

double ScannerTable::tableDistance(glm::dvec2 p) const {
  const glm::dvec2 centre(0.0, padTopMm - curvatureRadiusMm);
  return curvedLayerDistance(p, centre, curvatureRadiusMm, curvatureRadiusMm + padMm + shellMm,
                             halfWidthMm);
}

double ScannerTable::shellDistance(glm::dvec2 p) const {
  const glm::dvec2 centre(0.0, padTopMm - curvatureRadiusMm);
  return curvedLayerDistance(p, centre, curvatureRadiusMm + padMm, curvatureRadiusMm + padMm + shellMm,
                             halfWidthMm);
}

double signedDistance(const Solid& solid, glm::dvec3 p) {
  return std::visit([&](const auto& shape) { return signedDistance(shape, p); }, solid);
}

Bounds boundsOf(const Solid& solid) {
  return std::visit([](const auto& shape) { return boundsOf(shape); }, solid);
}

namespace {

// ---- Body outline

// Rows of a profile, highest z first: z, then values interpolated linearly in z (clamped at the
// ends); the result is a row too.
template <std::size_t N>
using ProfileRow = std::array<double, N>;

template <std::size_t N>
ProfileRow<N> interpolateProfile(const std::vector<ProfileRow<N>>& rows, double z) {
  std::size_t upper = 0;
  while (upper + 2 < rows.size() && rows[upper + 1][0] > z) ++upper;
  const ProfileRow<N>& a = rows[upper];
  const ProfileRow<N>& b = rows[upper + 1];
  const double t = std::clamp((a[0] - z) / (a[0] - b[0]), 0.0, 1.0);
  ProfileRow<N> values{};
  for (std::size_t n = 0; n < N; ++n) values[n] = glm::mix(a[n], b[n], t);
  return values;
}

// Torso: z, centre y, half-width, half-depth, fat thickness (mm).
const std::vector<ProfileRow<5>> kTorso = {{1200, 5, 158, 118, 22}, {1100, 5, 160, 120, 25},
                                           {1030, 5, 168, 118, 25}, {950, 10, 178, 112, 22},
                                           {900, 12, 178, 108, 20}, {860, 15, 172, 100, 18}};
constexpr double kTorsoCapTopMm = 860;  // below it the torso rounds off to the crotch
constexpr double kTorsoCapDepthMm = 40;
constexpr double kTorsoWallMm = 12;

// Left leg: z, centre x, centre y, radius x, radius y, fat thickness (mm).
const std::vector<ProfileRow<6>> kLeftLeg = {
    {930, 92, 15, 86, 86, 20}, {840, 92, 18, 82, 80, 18}, {740, 93, 22, 72, 70, 16},
    {640, 94, 32, 63, 62, 13}, {560, 95, 45, 58, 58, 9},  {500, 95, 50, 57, 58, 7},
    {440, 94, 55, 57, 58, 8},  {370, 93, 58, 58, 60, 9},  {280, 91, 55, 50, 52, 8},
    {190, 90, 46, 40, 44, 6},  {120, 89, 42, 37, 41, 4},  {70, 88, 42, 38, 44, 3},
    {55, 88, 42, 38, 44, 3}};
constexpr double kLegBottomMm = 55;  // below it the foot solid takes over

std::vector<FootPart> feet() {
  std::vector<FootPart> parts;
  for (double side : {1.0, -1.0}) {
    // Heel to instep, instep to toes.
    parts.push_back({{{85 * side, 62, 50}, {87 * side, -30, 40}, 42, 32}, 5});
    parts.push_back({{{87 * side, -30, 40}, {88 * side, -110, 28}, 32, 20}, 5});
  }
  return parts;
}

// ---- Bones

// Shell thickness and density, core density, ground-truth label, core texture.
struct ShellMaterial {
  double shellMm;
  double shellHu;
  double coreHu;
  int label = kBoneLabel;
  double coreTextureHu = 0;
};

// The shelled materials of one style.
struct Materials {
  ShellMaterial vertebra, flatBone, epiphysis, metaphysis, femurShaft, tibiaShaft, fibulaShaft,
      metatarsal, kidney;
};

// Simple: untextured cores; epiphysis = ends of long bones, patella, tarsals; the shafts' thick
// cortex around fatty marrow. Arterial phase: the renal cortex enhances, the medulla not yet.
constexpr Materials kSimpleMaterials{.vertebra = {1.5, 800, 220},
                                     .flatBone = {2.0, 1000, 200},
                                     .epiphysis = {1.5, 900, 210},
                                     .metaphysis = {2.0, 1000, 190},
                                     .femurShaft = {5.5, 1500, 40},
                                     .tibiaShaft = {4.5, 1500, 40},
                                     .fibulaShaft = {2.5, 1400, 40},
                                     .metatarsal = {1.5, 1200, 60},
                                     .kidney = {7.0, 190, 110, 0}};

// Realistic: cancellous bone of adults reads about 150-450 HU, mottled by the trabeculae a CT
// cannot resolve; adult long-bone marrow is yellow (fatty, -100..0 HU); cortex 1000-1600 HU; in
// the arterial (corticomedullary) phase the renal cortex reads 150-200 HU, the medulla about 100.
constexpr Materials kRealisticMaterials{.vertebra = {1.5, 1000, 280, kBoneLabel, 80},
                                        .flatBone = {2.0, 1100, 260, kBoneLabel, 80},
                                        .epiphysis = {1.5, 1000, 320, kBoneLabel, 80},
                                        .metaphysis = {2.0, 1100, 280, kBoneLabel, 80},
                                        .femurShaft = {5.5, 1600, -40, kBoneLabel, 25},
                                        .tibiaShaft = {4.5, 1600, -40, kBoneLabel, 25},
                                        .fibulaShaft = {2.5, 1500, -20, kBoneLabel, 25},
                                        .metatarsal = {1.5, 1200, 220, kBoneLabel, 60},
                                        .kidney = {7.0, 180, 100, 0, 10}};

// Portal-venous (nephrographic) phase: cortex and medulla alike, about 160-180 HU.
constexpr Materials kPortalVenousMaterials = [] {
  Materials m = kRealisticMaterials;
  m.kidney = {7.0, 175, 165, 0, 10};
  return m;
}();

constexpr double kDiscHu = 90;

Capsule capsule(glm::dvec3 a, glm::dvec3 b, double ra, double rb) { return {a, b, ra, rb}; }
Ellipsoid ellipsoid(glm::dvec3 centre, glm::dvec3 radii) { return {centre, glm::dmat3(1.0), radii}; }

void addShelled(std::vector<ShelledPart>& bones, Solid solid, const ShellMaterial& material) {
  bones.push_back({std::move(solid), material.shellMm, material.shellHu, material.coreHu, material.label,
                   material.coreTextureHu});
}

// Lumbar vertebra L1..L5 centred at height z: body (elliptic cylinder) and posterior arch.
void addVertebra(std::vector<ShelledPart>& bones, const ShellMaterial& material, double z) {
  addShelled(bones, EllipticCylinder{{0, 40, z}, {25, 19}, 14, 3}, material);
  for (double s : {1.0, -1.0}) {
    // Pedicle, lamina, transverse process, articular processes.
    addShelled(bones, capsule({15 * s, 52, z + 4}, {16 * s, 66, z + 4}, 5.5, 5.5), material);
    addShelled(bones, capsule({16 * s, 68, z}, {0, 80, z - 4}, 4.5, 4.5), material);
    addShelled(bones, capsule({16 * s, 64, z + 5}, {45 * s, 70, z + 7}, 4.5, 3.5), material);
    addShelled(bones, capsule({17 * s, 70, z + 12}, {17 * s, 70, z - 12}, 5, 5), material);
  }
  addShelled(bones, capsule({0, 80, z - 4}, {0, 95, z - 10}, 5, 4), material);  // spinous process
}

void addSpine(Anatomy& anatomy, const Materials& m) {
  constexpr double kPitchMm = 38;  // vertebral body 28 mm + disc 10 mm
  constexpr double kL5Mm = 1045;
  for (int level = 0; level < 5; ++level) {
    const double z = kL5Mm + level * kPitchMm;
    addVertebra(anatomy.shelled, m.vertebra, z);
    anatomy.softParts.push_back(
        {EllipticCylinder{{0, 40, z - kPitchMm / 2}, {23, 17}, 5.5, 2}, kDiscHu});
  }
  // Sacrum (tilted back) and coccyx, with the alae reaching the iliac wings.
  addShelled(anatomy.shelled, ellipsoid({0, 52, 1003}, {44, 22, 20}), m.flatBone);
  addShelled(anatomy.shelled, ellipsoid({0, 64, 968}, {36, 17, 20}), m.flatBone);
  addShelled(anatomy.shelled, ellipsoid({0, 77, 935}, {24, 12, 18}), m.flatBone);
  addShelled(anatomy.shelled, capsule({0, 85, 918}, {0, 80, 885}, 6, 4), m.flatBone);
  for (double s : {1.0, -1.0}) {
    addShelled(anatomy.shelled, ellipsoid({40 * s, 65, 995}, {18, 18, 30}), m.flatBone);
  }
}

// One half of the pelvis (s = +1 left, -1 right): iliac wing, acetabulum, pubic and ischial rami.
void addHemipelvis(std::vector<ShelledPart>& bones, const Materials& m, double s) {
  addShelled(bones, uprightPlate({85 * s, 30, 1000}, {75 * s, -90}, {65, 52, 9}), m.flatBone);
  addShelled(bones, ellipsoid({72 * s, 28, 930}, {22, 24, 28}), m.flatBone);  // acetabulum
  addShelled(bones, capsule({65 * s, 2, 915}, {10 * s, -28, 895}, 9, 8), m.flatBone);
  addShelled(bones, capsule({10 * s, -28, 895}, {12 * s, -18, 865}, 8, 8), m.flatBone);
  addShelled(bones, capsule({12 * s, -18, 865}, {52 * s, 42, 858}, 7, 7), m.flatBone);
  addShelled(bones, capsule({72 * s, 38, 925}, {55 * s, 48, 860}, 14, 12), m.flatBone);  // ischium
}

void addFemur(std::vector<ShelledPart>& bones, const Materials& m, double s) {
  addShelled(bones, ellipsoid({88 * s, 15, 905}, {23, 23, 23}), m.epiphysis);               // head
  addShelled(bones, capsule({88 * s, 15, 905}, {122 * s, 26, 878}, 15, 15), m.metaphysis);  // neck
  addShelled(bones, ellipsoid({130 * s, 30, 885}, {17, 22, 24}), m.epiphysis);  // greater trochanter
  addShelled(bones, ellipsoid({108 * s, 38, 850}, {9, 10, 12}), m.epiphysis);   // lesser trochanter
  addShelled(bones, capsule({124 * s, 30, 880}, {121 * s, 31, 830}, 18, 15), m.metaphysis);
  addShelled(bones, capsule({124 * s, 30, 860}, {98 * s, 42, 565}, 14.5, 13.5), m.femurShaft);
  addShelled(bones, capsule({98 * s, 42, 615}, {96 * s, 44, 535}, 14, 30), m.metaphysis);
  addShelled(bones, ellipsoid({76 * s, 45, 512}, {19, 28, 24}), m.epiphysis);   // medial condyle
  addShelled(bones, ellipsoid({115 * s, 45, 512}, {19, 28, 24}), m.epiphysis);  // lateral condyle
  addShelled(bones, ellipsoid({95 * s, 6, 522}, {22, 8, 22}), m.epiphysis);     // patella
}

void addTibiaAndFibula(std::vector<ShelledPart>& bones, const Materials& m, double s) {
  addShelled(bones, ellipsoid({93 * s, 45, 466}, {38, 27, 18}), m.epiphysis);  // plateau
  addShelled(bones, capsule({92 * s, 40, 462}, {88 * s, 32, 420}, 26, 14), m.metaphysis);
  addShelled(bones, ellipsoid({92 * s, 20, 440}, {12, 8, 15}), m.epiphysis);  // tuberosity
  addShelled(bones, capsule({88 * s, 30, 440}, {86 * s, 32, 130}, 13, 11), m.tibiaShaft);
  addShelled(bones, ellipsoid({86 * s, 38, 102}, {24, 22, 26}), m.epiphysis);   // distal tibia
  addShelled(bones, ellipsoid({70 * s, 38, 78}, {7, 10, 14}), m.epiphysis);     // medial malleolus
  addShelled(bones, ellipsoid({121 * s, 62, 448}, {11, 11, 13}), m.epiphysis);  // fibular head
  addShelled(bones, capsule({121 * s, 62, 440}, {115 * s, 55, 95}, 7, 6.5), m.fibulaShaft);
  addShelled(bones, ellipsoid({114 * s, 55, 78}, {8, 11, 20}), m.epiphysis);  // lateral malleolus
}

void addFootBones(std::vector<ShelledPart>& bones, const Materials& m, double s) {
  addShelled(bones, ellipsoid({85 * s, 42, 60}, {20, 26, 15}), m.epiphysis);  // talus
  addShelled(bones, ellipsoid({85 * s, 64, 36}, {20, 30, 20}), m.epiphysis);  // calcaneus
  addShelled(bones, ellipsoid({85 * s, 2, 40}, {27, 20, 15}), m.epiphysis);   // midfoot
  for (int ray = 0; ray < 5; ++ray) {
    const double x = (85 + 10.0 * (ray - 2)) * s;  // first metatarsal medial
    addShelled(bones, capsule({x, -15, 36}, {x, -85, 22}, 4, 3.5), m.metatarsal);
  }
}

// Lower two thirds of the kidneys, beside the upper lumbar spine (the box ends at L1).
void addKidneys(std::vector<ShelledPart>& shelled, const Materials& m) {
  for (double s : {1.0, -1.0}) {
    addShelled(shelled, ellipsoid({72 * s, 52, 1160}, {30, 24, 58}), m.kidney);
  }
}

// ---- Arteries

// Contrast fades slightly from the aorta to the feet (the bolus), within 330..430 HU.
double lumenHu(double distanceFromRootMm) {
  return 430.0 - 100.0 * std::min(1.0, distanceFromRootMm / 1400.0);
}

// Portal-venous phase: the arteries read 150..185 HU, hardly more than the veins beside them.
double portalVenousLumenHu(double distanceFromRootMm) {
  return 185.0 - 35.0 * std::min(1.0, distanceFromRootMm / 1400.0);
}

using LumenHu = double (*)(double);

void addArteries(Anatomy& anatomy, const ArterialTree& tree, LumenHu lumenHu) {
  std::vector<double> startDistance(tree.branches.size(), 0.0);
  for (std::size_t b = 0; b < tree.branches.size(); ++b) {
    const ArteryBranch& branch = tree.branches[b];
    if (branch.parent >= 0) {
      const ArteryBranch& parent = tree.branches[branch.parent];
      startDistance[b] = startDistance[branch.parent] + arcLengths(parent.points).back();
    }
    const std::vector<double> lengths = arcLengths(branch.points);
    for (std::size_t n = 0; n + 1 < branch.points.size(); ++n) {
      const CurvePoint& a = branch.points[n];
      const CurvePoint& c = branch.points[n + 1];
      anatomy.lumen.push_back(
          {capsule(a.position, c.position, a.radius, c.radius), lumenHu(startDistance[b] + lengths[n])});
    }
  }
  // The aorta goes on above the box, so it does not end in a visible cap at the top slice.
  const CurvePoint& top = tree.branches.front().points.front();
  anatomy.lumen.push_back(
      {capsule(top.position, top.position + glm::dvec3(0, 0, 60), top.radius, top.radius), lumenHu(0)});
  for (const Plaque& plaque : tree.plaques) {
    anatomy.plaques.push_back(
        {capsule(plaque.centre, plaque.centre, plaque.radiusMm, plaque.radiusMm), plaque.hu});
  }
  anatomy.paths = rootToLeafPaths(tree);
}

}  // namespace

std::vector<BodySection> bodySectionsAt(double zMm) {
  std::vector<BodySection> sections;
  const double capBottom = kTorsoCapTopMm - kTorsoCapDepthMm;
  if (zMm > capBottom) {
    const auto [z, cy, a, b, fat] = interpolateProfile(kTorso, zMm);
    const double below = std::max(0.0, kTorsoCapTopMm - zMm) / kTorsoCapDepthMm;
    const double shrink = std::sqrt(std::max(0.0, 1.0 - below * below));  // elliptical cap
    sections.push_back({{0, cy}, {a * shrink, b * shrink}, fat, kTorsoWallMm});
  }
  if (zMm >= kLegBottomMm && zMm <= kLeftLeg.front()[0]) {
    const auto [z, cx, cy, rx, ry, fat] = interpolateProfile(kLeftLeg, zMm);
    for (double side : {1.0, -1.0}) sections.push_back({{cx * side, cy}, {rx, ry}, fat, 0.0});
  }
  return sections;
}

Anatomy buildAnatomy(PhantomStyle style) {
  const bool realistic = style != PhantomStyle::simple;
  const bool portalVenous = style == PhantomStyle::portalVenous;
  const Materials& m = portalVenous ? kPortalVenousMaterials
                       : realistic  ? kRealisticMaterials
                                    : kSimpleMaterials;
  const LumenHu lumen = portalVenous ? portalVenousLumenHu : lumenHu;
  Anatomy anatomy;
  anatomy.feet = feet();
  addSpine(anatomy, m);
  addKidneys(anatomy.shelled, m);
  for (double s : {1.0, -1.0}) {
    addHemipelvis(anatomy.shelled, m, s);
    addFemur(anatomy.shelled, m, s);
    addTibiaAndFibula(anatomy.shelled, m, s);
    addFootBones(anatomy.shelled, m, s);
  }
  const ArterialTree tree = buildArterialTree();
  addArteries(anatomy, tree, lumen);
  if (realistic) addRealisticTissue(anatomy, tree, std::function<double(double)>(lumen), style);
  return anatomy;
}

}  // namespace angio::phantom
