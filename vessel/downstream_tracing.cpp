#include "vessel/downstream_tracing.h"

#include <algorithm>
#include <cmath>

#include "core/voxel.h"
#include "vessel/lumen_paths.h"

namespace angio {

namespace {

// Which of the tree's nodes some branch covers already.
class Coverage {
 public:
  Coverage(const LumenField& field, const LumenTree& tree, double coverRadii)
      : field_(field), tree_(tree), coverRadii_(coverRadii), covered_(tree.nodes().size(), false),
        byLength_(tree.nodes().size()) {
    for (std::size_t n = 0; n < byLength_.size(); ++n) byLength_[n] = n;
    std::stable_sort(byLength_.begin(), byLength_.end(), [&](std::size_t a, std::size_t b) {
      return tree.nodes()[a].lengthMm > tree.nodes()[b].lengthMm;
    });
  }

  bool isCovered(std::size_t node) const { return covered_[node]; }

  // Covers the voxels within coverRadii * radius + 1 mm of each voxel of a chain.
  void coverAround(const std::vector<glm::ivec3>& chain) {
    const glm::dvec3 spacing = field_.spacing();
    for (const glm::ivec3& centre : chain) {
      const double reachMm = coverRadii_ * field_.wallDistanceMm(centre) + 1.0;
      const glm::ivec3 reach = glm::ivec3(glm::ceil(reachMm / spacing));
      for (int dk = -reach.z; dk <= reach.z; ++dk)
        for (int dj = -reach.y; dj <= reach.y; ++dj)
          for (int di = -reach.x; di <= reach.x; ++di) {
            const glm::ivec3 voxel = centre + glm::ivec3(di, dj, dk);
            if (!field_.isLumen(voxel)) continue;
            if (glm::length(glm::dvec3(di, dj, dk) * spacing) > reachMm) continue;
            if (const auto node = tree_.nodeOf(field_.offsetOf(voxel))) covered_[*node] = true;
          }
    }
  }

  // The uncovered node farthest along the tree, none when all are covered. Coverage only grows,
  // so the search goes on from where the last one stopped.
  std::optional<std::size_t> farthestUncovered() {
    while (next_ < byLength_.size() && covered_[byLength_[next_]]) ++next_;
    if (next_ == byLength_.size()) return std::nullopt;
    return byLength_[next_];
  }

 private:
  const LumenField& field_;
  const LumenTree& tree_;
  double coverRadii_;
  std::vector<bool> covered_;
  std::vector<std::size_t> byLength_;  // node indices, farthest first
  std::size_t next_ = 0;
};

// From `leaf` back towards the root up to the first covered node (or the root): that node.
std::size_t branchStart(const LumenTree& tree, const Coverage& coverage, std::size_t leaf) {
  std::size_t node = leaf;
  while (!coverage.isCovered(node) && tree.nodes()[node].parent != node)
    node = tree.nodes()[node].parent;
  return node;
}

// The mean distance to the wall along a chain's voxels from `first` on.
double meanWallMm(const LumenField& field, const std::vector<glm::ivec3>& chain, std::size_t first) {
  double sum = 0;
  for (std::size_t n = first; n < chain.size(); ++n) sum += field.wallDistanceMm(chain[n]);
  return chain.size() > first ? sum / double(chain.size() - first) : 0.0;
}

// The median density along a chain's voxels from `first` on.
double medianDensity(const Volume& volume, const std::vector<glm::ivec3>& chain, std::size_t first) {
  std::vector<int> densities;
  for (std::size_t n = first; n < chain.size(); ++n)
    densities.push_back(volume.densityAt(chain[n].x, chain[n].y, chain[n].z));
  if (densities.empty()) return 0;
  std::nth_element(densities.begin(), densities.begin() + densities.size() / 2, densities.end());
  return densities[densities.size() / 2];
}

}  // namespace

std::vector<std::vector<glm::ivec3>> downstreamChains(const Volume& volume, const LumenField& field,
                                                      glm::ivec3 root,
                                                      const DownstreamSettings& settings,
                                                      const std::atomic<bool>* cancel,
                                                      const std::function<void(double)>& progress) {
  const LumenTree tree(field, root, settings.coreWallMm, cancel);
  if (tree.isCancelled() || tree.nodes().empty()) return {};
  Coverage coverage(field, tree, settings.coverRadii);
  const double low = densityOfHu(field.range().lowHu);
  const double minDensity =
      low + settings.minContrastFraction * (volume.densityAt(root.x, root.y, root.z) - low);
  std::vector<std::vector<glm::ivec3>> chains;
  for (std::optional<std::size_t> leaf = coverage.farthestUncovered();
       leaf && int(chains.size()) < settings.maxPaths; leaf = coverage.farthestUncovered()) {
    if (cancel && cancel->load()) return {};
    const std::size_t start = branchStart(tree, coverage, *leaf);
    const double beyondMm = tree.nodes()[*leaf].lengthMm - tree.nodes()[start].lengthMm;
    const double parentRadiusMm = field.wallDistanceAt(tree.nodes()[start].offset);
    std::vector<glm::ivec3> chain = tree.pathTo(*leaf);
    // The new part only: the trunk before `start` was covered with its own branch.
    const std::size_t trunk = tree.pathTo(start).size() - 1;
    coverage.coverAround({chain.begin() + std::ptrdiff_t(trunk), chain.end()});
    const double outsideParentMm = beyondMm - parentRadiusMm;
    const bool isVessel =
        chains.empty() || (outsideParentMm >= settings.minBranchMm &&
                           outsideParentMm >= settings.minElongation * meanWallMm(field, chain, trunk));
    if (isVessel) chains.push_back(std::move(chain));
    if (progress) progress(double(chains.size()) / settings.maxPaths);
  }
  return chains;
}

}  // namespace angio
