#pragma once
// The phantom's arterial tree: aorta -> common and external iliac -> femoral -> popliteal ->
// anterior and posterior tibial, both legs, in the anatomy frame (core/phantom_anatomy.h).
// Each branch is a smooth curve through hand-placed knots; the external iliacs and the right
// superficial femoral wiggle (tortuous segments), the anterior tibials leave the popliteal and
// cross the foot nearly horizontally (so do the posterior tibials along the sole), the left
// superficial femoral has a stenosis to 40%, and calcified plaques sit on the walls.
#include <string>
#include <vector>

#include "phantom/phantom.h"
#include "phantom/phantom_geometry.h"

namespace angio::phantom {

// One branch after construction: points every ~1 mm from its first point (the parent's last point,
// or the root) to its end, radius in mm.
struct ArteryBranch {
  std::string name;
  int parent = -1;  // index into the branch list; -1 for the root
  std::vector<CurvePoint> points;
};

struct Plaque {
  glm::dvec3 centre{0.0};
  double radiusMm = 0;
  double hu = 0;
};

struct ArterialTree {
  std::vector<ArteryBranch> branches;  // parents before children
  std::vector<Plaque> plaques;
};

ArterialTree buildArterialTree();

// Root-to-leaf paths (shared trunks repeated, as vmtk writes them), named
// "aorta-<leaf branch name>", in the anatomy frame.
std::vector<CenterlinePath> rootToLeafPaths(const ArterialTree& tree);

}  // namespace angio::phantom
