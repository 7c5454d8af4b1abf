#include "phantom/phantom_organs.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "core/labels.h"

namespace angio::phantom {

namespace {

// A fixed-seed generator of its own (splitmix64), so the layout does not depend on the standard
// library's distributions.
struct Rng {
  std::uint64_t state = 0x5eed0f0a1a70113full;

  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * double(next() >> 11) * 0x1.0p-53; }
  bool chance(double p) { return uniform(0, 1) < p; }
  glm::dvec3 unitVector() {
    const double z = uniform(-1, 1);
    const double phi = uniform(0, 2 * std::numbers::pi);
    const double r = std::sqrt(1 - z * z);
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
};

Ellipsoid ellipsoid(glm::dvec3 centre, glm::dvec3 radii) { return {centre, glm::dmat3(1.0), radii}; }
Capsule capsule(glm::dvec3 a, glm::dvec3 b, double ra, double rb) { return {a, b, ra, rb}; }

// Arterial-phase densities (HU): the liver is still mostly supplied by the unenhanced portal vein,
// the spleen enhances heterogeneously, the pancreas strongly; urine is not yet opacified.
const Ellipsoid kLiver = ellipsoid({-65, 0, 1195}, {50, 55, 70});
const Ellipsoid kSpleen = ellipsoid({88, 25, 1190}, {20, 30, 48});

// Portal-venous phase (about 70 s): the liver enhances through the portal vein to 100-130 HU, the
// spleen becomes homogeneous, the pancreas fades below the liver.
struct OrganDensities {
  double liver, liverTexture, spleen, spleenTexture, pancreas;
};
constexpr OrganDensities kArterialOrgans{95, 8, 118, 20, 125};
constexpr OrganDensities kPortalVenousOrgans{115, 8, 120, 8, 105};

void addOrgans(std::vector<FilledPart>& soft, const OrganDensities& d) {
  soft.push_back({kLiver, d.liver, d.liverTexture});
  soft.push_back({kSpleen, d.spleen, d.spleenTexture});
  soft.push_back({capsule({-5, -15, 1170}, {62, 14, 1186}, 10, 8), d.pancreas, 10});  // pancreas
  soft.push_back({ellipsoid({0, -5, 905}, {40, 28, 30}), 10, 0});                     // bladder
  for (double s : {1.0, -1.0}) {
    soft.push_back({capsule({28 * s, 48, 1205}, {52 * s, 25, 950}, 13, 18), 60, 5});  // psoas
  }
}

// ---- Bowel: enhancing wall (mucosa) around fluid or gas

struct BowelMaterial {
  double wallMm, wallHu, contentHu, contentTextureHu;
};
constexpr BowelMaterial kFluidLoop{2.5, 130, 20, 10};
constexpr BowelMaterial kGasLoop{2.5, 130, -750, 60};
constexpr BowelMaterial kColon{2.0, 110, -800, 80};

void addBowel(std::vector<ShelledPart>& shelled, const Capsule& shape, const BowelMaterial& m) {
  shelled.push_back({shape, m.wallMm, m.wallHu, m.contentHu, 0, m.contentTextureHu});
}

// Colon around the small bowel: ascending, transverse, descending, sigmoid and rectum.
void addColon(std::vector<ShelledPart>& shelled) {
  const std::vector<CurvePoint> knots = {
      {{-88, -20, 975}, 18}, {{-90, -25, 1105}, 18}, {{0, -45, 1100}, 17},
      {{90, -25, 1108}, 17}, {{88, -15, 975}, 16},   {{40, -20, 960}, 15},
      {{10, 20, 945}, 14},   {{0, 38, 940}, 13},     {{0, 35, 885}, 13}};
  for (std::size_t n = 0; n + 1 < knots.size(); ++n) {
    const CurvePoint& a = knots[n];
    const CurvePoint& b = knots[n + 1];
    addBowel(shelled, capsule(a.position, b.position, a.radius, b.radius), kColon);
  }
}

// Small bowel: random walks of capsules kept in the anterior abdomen, clear of the spine, the iliac
// wings and the acetabula.
void addSmallBowel(std::vector<ShelledPart>& shelled, Rng& rng) {
  const glm::dvec3 lo(-70, -50, 965), hi(70, 0, 1095);
  constexpr int kLoops = 10, kSteps = 12;
  constexpr double kStepMm = 18;
  for (int loop = 0; loop < kLoops; ++loop) {
    const BowelMaterial& material = rng.chance(0.25) ? kGasLoop : kFluidLoop;
    const double radius = rng.uniform(10, 13);
    glm::dvec3 p(rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y), rng.uniform(lo.z, hi.z));
    glm::dvec3 direction = rng.unitVector();
    for (int step = 0; step < kSteps; ++step) {
      direction = glm::normalize(direction + 0.8 * rng.unitVector());
      glm::dvec3 next = p + kStepMm * direction;
      for (int axis = 0; axis < 3; ++axis) {  // reflect off the region's walls
        if (next[axis] < lo[axis] || next[axis] > hi[axis]) direction[axis] = -direction[axis];
      }
      next = glm::clamp(p + kStepMm * direction, lo, hi);
      addBowel(shelled, capsule(p, next, radius, radius), material);
      p = next;
    }
  }
}

// ---- Small arteries

// A branch to grow: from start along direction, lengthMm long, radius tapering to kTipRadiusMm.
struct Sprout {
  glm::dvec3 start{0.0};
  glm::dvec3 direction{0, 0, 1};
  double radiusMm = 1;
  double lengthMm = 30;
  double hu = 350;
  int generation = 0;
};

constexpr double kTipRadiusMm = 0.5;
constexpr int kSegmentsPerBranch = 4;

// Where small arteries may run (a predicate on points, anatomy frame).
using Allowed = std::function<bool(glm::dvec3)>;

// Grows a sprout into capsules (a wiggling, tapering branch), stopping where it would leave the
// allowed region; some segments sprout a thinner side branch of their own.
void grow(const Sprout& root, const Allowed& allowed, Rng& rng, std::vector<FilledPart>& lumen) {
  std::vector<Sprout> pending{root};
  while (!pending.empty()) {
    const Sprout sprout = pending.back();
    pending.pop_back();
    glm::dvec3 p = sprout.start, direction = sprout.direction;
    double radius = sprout.radiusMm;
    const double step = sprout.lengthMm / kSegmentsPerBranch;
    for (int s = 1; s <= kSegmentsPerBranch; ++s) {
      direction = glm::normalize(direction + 0.45 * rng.unitVector());
      const glm::dvec3 next = p + step * direction;
      if (!allowed(next)) break;
      const double nextRadius = glm::mix(sprout.radiusMm, kTipRadiusMm, double(s) / kSegmentsPerBranch);
      lumen.push_back({capsule(p, next, radius, nextRadius), sprout.hu});
      if (sprout.generation < 2 && rng.chance(0.5)) {
        const glm::dvec3 side = glm::normalize(perpendicular(direction) + 0.3 * rng.unitVector());
        pending.push_back({next, side, std::max(kTipRadiusMm, 0.8 * nextRadius), 0.6 * sprout.lengthMm,
                           sprout.hu, sprout.generation + 1});
      }
      p = next;
      radius = nextRadius;
    }
  }
}

// Inside the body deeper than its subcutaneous fat (in muscle or the abdomen), above the feet.
bool underTheFat(glm::dvec3 p, double marginMm) {
  if (p.z < 70) return false;
  for (const BodySection& s : bodySectionsAt(p.z)) {
    if (ellipseSignedDistance(glm::dvec2(p) - s.centre, s.radii) < -(s.fatMm + kSkinMm + marginMm))
      return true;
  }
  return false;
}

bool clearOfBone(const std::vector<ShelledPart>& shelled, glm::dvec3 p, double marginMm) {
  return std::none_of(shelled.begin(), shelled.end(), [&](const ShelledPart& part) {
    return part.label == kBoneLabel && signedDistance(part.solid, p) < marginMm;
  });
}

// Muscular branches every ~6 mm along the tree (every ~12 mm along the aorta).
void addMuscularBranches(Anatomy& anatomy, const ArterialTree& tree,
                         const std::function<double(double)>& lumenHu, const Allowed& allowed,
                         Rng& rng) {
  std::vector<double> startDistance(tree.branches.size(), 0.0);
  for (std::size_t b = 0; b < tree.branches.size(); ++b) {
    const ArteryBranch& branch = tree.branches[b];
    const std::vector<double> lengths = arcLengths(branch.points);
    if (branch.parent >= 0) {
      startDistance[b] =
          startDistance[branch.parent] + arcLengths(tree.branches[branch.parent].points).back();
    }
    const double spacing = b == 0 ? 12 : 6;
    double nextAt = 10;
    for (std::size_t n = 1; n + 1 < branch.points.size(); ++n) {
      if (lengths[n] < nextAt) continue;
      nextAt = lengths[n] + spacing * rng.uniform(0.7, 1.3);
      const glm::dvec3 tangent =
          glm::normalize(branch.points[n + 1].position - branch.points[n - 1].position);
      const double angle = rng.uniform(0, 2 * std::numbers::pi);
      const glm::dvec3 across = perpendicular(tangent);
      const glm::dvec3 out = glm::normalize(
          across * std::cos(angle) + glm::cross(tangent, across) * std::sin(angle) + 0.3 * tangent);
      const CurvePoint& at = branch.points[n];
      grow({at.position + 0.5 * at.radius * out, out, rng.uniform(0.55, 1.4), rng.uniform(30, 80),
            lumenHu(startDistance[b] + lengths[n])},
           allowed, rng, anatomy.lumen);
    }
  }
}

// Arteries inside an organ, from its hilum outwards, kept inside it.
void addOrganBranches(std::vector<FilledPart>& lumen, const Solid& organ, glm::dvec3 hilum, int count,
                      double hu, Rng& rng) {
  const Allowed inside = [&](glm::dvec3 p) { return signedDistance(organ, p) < -1.5; };
  for (int n = 0; n < count; ++n) {
    grow({hilum, rng.unitVector(), rng.uniform(0.8, 1.4), rng.uniform(25, 45), hu}, inside, rng, lumen);
  }
}

void addRenalArteries(Anatomy& anatomy, double hu) {
  for (double s : {1.0, -1.0}) {
    // From the aorta round the front of the vertebral body to the hilum.
    const std::vector<glm::dvec3> knots = {{14, 5, 1150},
                                           {(s > 0 ? 35 : -20), (s > 0 ? 12 : 8), 1153},
                                           {(s > 0 ? 48 : -40), (s > 0 ? 40 : 25), 1157},
                                           {48 * s, 48, 1160}};
    for (std::size_t n = 0; n + 1 < knots.size(); ++n) {
      anatomy.lumen.push_back({capsule(knots[n], knots[n + 1], 2.6, 2.4), hu});
    }
  }
}

void addSmallArteries(Anatomy& anatomy, const ArterialTree& tree,
                      const std::function<double(double)>& lumenHu, Rng& rng) {
  const std::vector<ShelledPart> bones = anatomy.shelled;  // bowel is added afterwards
  const Allowed inMuscle = [&](glm::dvec3 p) { return underTheFat(p, 3) && clearOfBone(bones, p, 1.5); };
  addMuscularBranches(anatomy, tree, lumenHu, inMuscle, rng);
  const double hu = lumenHu(0);
  for (int n = 0; n < 15; ++n) {  // mesenteric branches, forward into the bowel
    const glm::dvec3 start(13, 4, rng.uniform(1100, 1180));
    const glm::dvec3 forward = glm::normalize(glm::dvec3(0, -1, -0.4) + 0.5 * rng.unitVector());
    grow({start, forward, rng.uniform(1.1, 1.5), rng.uniform(60, 100), hu}, inMuscle, rng,
         anatomy.lumen);
  }
  addRenalArteries(anatomy, hu);
  for (double s : {1.0, -1.0}) {
    addOrganBranches(anatomy.lumen, ellipsoid({72 * s, 52, 1160}, {30, 24, 58}), {48 * s, 50, 1160}, 12,
                     hu, rng);
  }
  addOrganBranches(anatomy.lumen, kLiver, {-30, 0, 1165}, 20, hu, rng);
  addOrganBranches(anatomy.lumen, kSpleen, {78, 15, 1185}, 10, hu, rng);
}

// ---- Veins (portal-venous phase): soft parts, so that bones, kidneys and bowel paint over them
// where a hand-placed course grazes one.

// Portal-venous densities (HU): the portal system brightest, the renal veins next, the cava and
// the leg veins less (unopacified blood from the legs still mixing in).
constexpr double kPortalHu = 180, kRenalVeinHu = 170, kCavaHu = 150, kIliacVeinHu = 140;
constexpr double kLegVeinHu = 130, kTibialVeinHu = 120;

void addVein(std::vector<FilledPart>& soft, const std::vector<CurvePoint>& knots, double hu) {
  for (std::size_t n = 0; n + 1 < knots.size(); ++n) {
    const CurvePoint& a = knots[n];
    const CurvePoint& b = knots[n + 1];
    soft.push_back({capsule(a.position, b.position, a.radius, b.radius), hu});
  }
}

CurvePoint at(double x, double y, double z, double r) { return {{x, y, z}, r}; }

// The cava right of the aorta (continuing above the box), the renal veins (the left one in front
// of the aorta), the portal vein with the splenic and superior mesenteric veins.
void addTrunkVeins(std::vector<FilledPart>& soft) {
  addVein(soft, {at(-14, 10, 1260, 11), at(-14, 10, 1195, 11), at(-13, 8, 1100, 10), at(-6, 8, 1050, 9)},
          kCavaHu);
  addVein(soft, {at(48, 48, 1160, 4), at(30, 15, 1162, 4), at(14, -6, 1163, 4), at(-12, 6, 1163, 5)},
          kRenalVeinHu);
  addVein(soft, {at(-48, 48, 1160, 4), at(-20, 14, 1160, 5)}, kRenalVeinHu);
  addVein(soft, {at(5, -2, 1175, 7), at(-30, 0, 1190, 7)}, kPortalHu);  // portal
  addVein(soft, {at(5, -2, 1175, 4.5), at(40, 10, 1180, 4.5), at(78, 15, 1185, 4)},
          kPortalHu);  // splenic
  addVein(soft, {at(5, -2, 1175, 5), at(8, -18, 1120, 4.5), at(10, -25, 1070, 4)}, kPortalHu);  // SMV
}

// Iliac, femoral and popliteal veins of one side (side = +1: the patient's left), medial and
// behind their arteries (phantom_arteries.cpp), from the cava's confluence to the knee.
void addLegVeins(std::vector<FilledPart>& soft, double side) {
  const auto s = [side](double x, double y, double z, double r) { return at(side * x, y, z, r); };
  addVein(soft,
          {at(-6, 8, 1050, 7), s(26, 16, 1020, 7), s(42, 24, 990, 6.5), s(56, 16, 960, 6),
           s(70, -4, 930, 6), s(77, -26, 900, 5.5)},
          kIliacVeinHu);
  addVein(
      soft,
      {s(77, -26, 900, 5.5), s(79, -30, 880, 5.5), s(76, -19, 800, 5.5), s(72, 0, 700, 5),
       s(66, 20, 630, 5), s(70, 70, 585, 5), s(88, 90, 540, 5), s(93, 96, 490, 5), s(94, 94, 432, 4.5)},
      kLegVeinHu);
}

// Two thin veins beside each tibial artery (venae comitantes), on either side of it.
void addTibialVeins(std::vector<FilledPart>& soft, const ArterialTree& tree) {
  for (const ArteryBranch& branch : tree.branches) {
    if (branch.name.find("tibial") == std::string::npos) continue;
    const std::vector<CurvePoint> course = resample(branch.points, 8);
    for (double pair : {1.0, -1.0}) {
      std::vector<CurvePoint> vein;
      for (std::size_t n = 0; n < course.size(); ++n) {
        const std::size_t next = std::min(n + 1, course.size() - 1), previous = n > 0 ? n - 1 : 0;
        const glm::dvec3 tangent = glm::normalize(course[next].position - course[previous].position);
        const double radius = 0.8 * course[n].radius;
        const glm::dvec3 offset = pair * (course[n].radius + radius + 0.5) * perpendicular(tangent);
        vein.push_back({course[n].position + offset, radius});
      }
      addVein(soft, vein, kTibialVeinHu);
    }
  }
}

void addVeins(Anatomy& anatomy, const ArterialTree& tree, Rng& rng) {
  addTrunkVeins(anatomy.softParts);
  for (double side : {1.0, -1.0}) addLegVeins(anatomy.softParts, side);
  addTibialVeins(anatomy.softParts, tree);
  // Portal branches through the liver, brighter than its parenchyma.
  addOrganBranches(anatomy.softParts, kLiver, {-30, 0, 1190}, 16, kPortalHu, rng);
}

}  // namespace

void addRealisticTissue(Anatomy& anatomy, const ArterialTree& tree,
                        const std::function<double(double)>& lumenHu, PhantomStyle style) {
  Rng rng;
  const bool portalVenous = style == PhantomStyle::portalVenous;
  addOrgans(anatomy.softParts, portalVenous ? kPortalVenousOrgans : kArterialOrgans);
  addSmallArteries(anatomy, tree, lumenHu, rng);
  addColon(anatomy.shelled);
  addSmallBowel(anatomy.shelled, rng);
  if (portalVenous) addVeins(anatomy, tree, rng);
}

}  // namespace angio::phantom
