#pragma once
// Tracing a vessel tree from one click: the cheapest paths from the click to every lumen voxel it
// reaches (vessel/lumen_paths.h LumenTree) are a tree; its branches are picked as TEASAR does
// (Sato et al., "TEASAR: tree-structure extraction algorithm for accurate and robust skeletons",
// 2000): the reached voxel farthest along the tree that no branch covers yet ends a new branch,
// which runs back until it meets a branch found before; the voxels within a multiple of the
// lumen radius around it are then covered. Branches shorter than a vessel's width beyond where
// they leave their parent are bumps of the wall, not vessels, and are dropped, as are branches no
// longer than a few of their widths (into a blob, not along a vessel).
#include <atomic>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "core/volume.h"
#include "vessel/lumen_field.h"

namespace angio {

struct DownstreamSettings {
  // Only voxels this far from the wall carry the tree; 0: all lumen voxels. On the voxel grid the
  // distance map of a 3 mm vessel dips to one voxel along its ridge, so a core threshold breaks
  // small vessels up (the phantom's pedal arteries end 50 mm early at 1 mm).
  double coreWallMm = 0;
  double minBranchMm = 10;  // beyond its parent's wall
  // A vessel is a tube: beyond its parent's wall a branch is this many times longer than its mean
  // radius. Branches into a blob (an enhancing organ, a bone's marrow in uncalibrated data) are
  // about as long as they are wide.
  double minElongation = 4;
  // A vessel is contrast-filled along its centre: the median density along a branch lies at least
  // this fraction of the way from the range's low end to the density at the click (the bolus fades
  // downstream, the phantom's by a quarter; tissue just inside the range does not pass).
  double minContrastFraction = 0.25;
  double coverRadii = 1.5;  // a branch covers the voxels within this many radii (+ 1 mm)
  int maxPaths = 64;

  friend bool operator==(const DownstreamSettings&, const DownstreamSettings&) = default;
};

// Root-to-leaf voxel chains, longest first; chains through one trunk share its voxels exactly
// (they are paths of one tree). Empty if the root is not lumen or `cancel` turned true.
std::vector<std::vector<glm::ivec3>> downstreamChains(const Volume& volume, const LumenField& field,
                                                      glm::ivec3 root,
                                                      const DownstreamSettings& settings,
                                                      const std::atomic<bool>* cancel = nullptr,
                                                      const std::function<void(double)>& progress = {});

}  // namespace angio
