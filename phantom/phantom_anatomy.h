#pragma once
// The phantom's anatomy as solids with materials, in the anatomy frame: x (mm) towards the
// patient's left of the midline, y (mm) posterior of the body's coronal mid-plane, z (mm) height
// above the bottom of the scanned box (soles a few mm above z = 0). Voxel axes i, j, k run along
// x, y, z.
// Proportions of an adult of about 1.75 m scanned from the upper lumbar spine to the feet.
#include <variant>
#include <vector>

#include "phantom/phantom.h"
#include "phantom/phantom_geometry.h"

namespace angio::phantom {

// The physical size of the scanned box (mm); voxel spacing = size / dims.
inline constexpr glm::dvec3 kBoxSizeMm{409.6, 409.6, 1200.0};

// Physical z (mm, LPS, scanner table coordinates) = anatomy z + this: the top of the box is at 0.
inline constexpr double kPhysicalZOffsetMm = -1200.0;

using Solid = std::variant<Capsule, Ellipsoid, EllipticCylinder>;

double signedDistance(const Solid& solid, glm::dvec3 p);
Bounds boundsOf(const Solid& solid);

// A region of one density (discs, organs, a piece of vessel lumen, a plaque); textureHu > 0 adds a
// smooth random texture of about that standard deviation (organ heterogeneity).
struct FilledPart {
  Solid solid;
  double hu = 0;
  double textureHu = 0;
};

// A solid with a shell of shellMm around a core: a bone (cortex around cancellous bone or marrow),
// a kidney (enhancing cortex around the medulla) or a bowel loop (enhancing wall around its
// contents). coreTextureHu > 0 textures the core (trabecular bone, marrow, bowel contents).
struct ShelledPart {
  Solid solid;
  double shellMm = 0;
  double shellHu = 0;
  double coreHu = 0;
  int label = 0;  // ground truth of the whole solid: kBoneLabel for bones, 0 for kidneys and bowel
  double coreTextureHu = 0;
};

// A cross-section of the body in one axial slice: an ellipse with skin, a subcutaneous fat layer of
// fatMm, and inside muscle; in the torso a muscle wall of wallMm around the viscera.
struct BodySection {
  glm::dvec2 centre{0.0};
  glm::dvec2 radii{0.0};
  double fatMm = 0;
  double wallMm = 0;  // 0: muscle all the way in (legs)
};

// The feet are not vertical: they are solids (with their own fat layer).
struct FootPart {
  Capsule shape;
  double fatMm = 0;
};

// The scanner table the patient lies on, the same in every axial slice: a carbon-fibre shell under a
// foam pad, both curved to follow the back (concave towards the patient, whose back rests on the
// pad's middle), a little wider than the body. Real tables read about -200..+300 HU in the shell and
// -800..-600 HU in the pad.
struct ScannerTable {
  double padTopMm = 121;  // y of the pad's top under the midline (the torso's back reaches ~125)
  double padMm = 25;
  double shellMm = 4;
  double curvatureRadiusMm = 500;  // of the pad's top; the centre is anterior, on the midline
  double halfWidthMm = 190;
  double padHu = -700;
  double shellHu = 100;

  // Signed distances (mm, negative inside) in the axial plane: to the whole table (pad and shell)
  // and to the shell alone.
  double tableDistance(glm::dvec2 p) const;
  double shellDistance(glm::dvec2 p) const;
};

struct Anatomy {
  ScannerTable table;
  std::vector<FootPart> feet;
  std::vector<FilledPart> softParts;  // painted over the body's layers
  std::vector<ShelledPart> shelled;   // bones and kidneys, over the soft parts
  std::vector<FilledPart> lumen;      // contrast-filled arteries, over the bones
  std::vector<FilledPart> plaques;    // calcium, over the lumen
  std::vector<CenterlinePath> paths;  // ground-truth centerlines in the anatomy frame
};

Anatomy buildAnatomy(PhantomStyle style);

// The body's axial cross-sections at height z (torso and/or legs; empty below the legs).
std::vector<BodySection> bodySectionsAt(double zMm);

// Skin, fat and muscle densities (HU) used for the body's layers.
inline constexpr double kAirHu = -1000;
inline constexpr double kSkinHu = 40;
inline constexpr double kFatHu = -100;
inline constexpr double kMuscleHu = 50;
inline constexpr double kVisceraHu = 30;
inline constexpr double kSkinMm = 2;

// The realistic style fills the abdominal cavity around its organs and bowel with visceral fat
// (mixed with mesentery) instead of uniform soft tissue.
inline constexpr double kRealisticVisceraHu = -80;
// Skeletal muscle enhances a little in the arterial phase.
inline constexpr double kRealisticMuscleHu = 60;

}  // namespace angio::phantom
