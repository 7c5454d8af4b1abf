#pragma once
// Cheapest paths through the lumen of a LumenField (Dijkstra on the voxel grid, 26 neighbours).
// A step costs its length over the squared distance to the wall at the voxel it enters, so paths
// keep to the distance map's ridge, the lumen's centre, instead of cutting the inner curve of a
// bend (the minimal-path centerlines of Deschamps and Cohen, with vmtk's inscribed-sphere radius
// as the speed). ITK's fast marching gives arrival times but its path extraction is a remote
// module Debian does not ship; on the voxel grid Dijkstra gives the path directly.
#include <atomic>
#include <cstddef>
#include <optional>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "vessel/lumen_field.h"

namespace angio {

// Voxels from `from` to `to` (both included) through lumen voxels, or none where no lumen path
// joins them (or `cancel` turned true).
std::optional<std::vector<glm::ivec3>> cheapestLumenPath(const LumenField& field, glm::ivec3 from,
                                                         glm::ivec3 to,
                                                         const std::atomic<bool>* cancel = nullptr);

// The cheapest paths from a root to every lumen voxel it reaches through voxels at least
// `minWallDistanceMm` from the wall (0: all; above it a thin bridge of partial-volume voxels
// between a vessel and a bone's cortex does not join them).
class LumenTree {
 public:
  struct Node {
    std::size_t offset = 0;  // in the field's box
    std::size_t parent = 0;  // node index; the root is its own parent
    double lengthMm = 0;     // along the path from the root
  };

  LumenTree(const LumenField& field, glm::ivec3 root, double minWallDistanceMm,
            const std::atomic<bool>* cancel = nullptr);

  bool isCancelled() const { return cancelled_; }
  const std::vector<Node>& nodes() const { return nodes_; }  // in the order Dijkstra settled them
  // Node index of a box offset, none if the voxel was not reached.
  std::optional<std::size_t> nodeOf(std::size_t offset) const;
  // The voxels from the root to node n (both included).
  std::vector<glm::ivec3> pathTo(std::size_t node) const;

 private:
  const LumenField* field_;
  std::vector<Node> nodes_;
  std::unordered_map<std::size_t, std::size_t> nodeOfOffset_;
  bool cancelled_ = false;
};

}  // namespace angio
