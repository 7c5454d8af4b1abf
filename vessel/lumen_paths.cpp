#include "vessel/lumen_paths.h"

#include <algorithm>
#include <array>
#include <limits>
#include <queue>

namespace angio {

namespace {

struct Neighbour {
  glm::ivec3 step;
  double lengthMm;
};

std::array<Neighbour, 26> neighboursOf(glm::dvec3 spacing) {
  std::array<Neighbour, 26> neighbours;
  int n = 0;
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        if (di == 0 && dj == 0 && dk == 0) continue;
        const glm::ivec3 step(di, dj, dk);
        neighbours[n++] = {step, glm::length(glm::dvec3(step) * spacing)};
      }
  return neighbours;
}

// The cost of a millimetre at a voxel `wallMm` from the wall (see the header).
double costPerMm(float wallMm) { return 1.0 / (double(wallMm) * wallMm); }

constexpr int kCancelCheckInterval = 4096;

// Dijkstra from `root` over the voxels whose wall distance is at least minWallMm (the root
// always), settling nodes until `target` is settled (if given) or the queue runs dry.
class Dijkstra {
 public:
  Dijkstra(const LumenField& field, double minWallMm)
      : field_(field), minWallMm_(minWallMm), neighbours_(neighboursOf(field.spacing())) {}

  // False when cancelled.
  bool run(glm::ivec3 root, std::optional<std::size_t> target, const std::atomic<bool>* cancel) {
    const std::size_t rootOffset = field_.offsetOf(root);
    tentative_[rootOffset] = {0.0, rootOffset, 0.0, false};
    queue_.push({0.0, rootOffset});
    for (int settledSinceCheck = 0; !queue_.empty();) {
      const auto [cost, offset] = queue_.top();
      queue_.pop();
      Entry& entry = tentative_[offset];
      if (entry.settled || cost > entry.cost) continue;
      entry.settled = true;
      settled_.push_back(offset);
      if (target && offset == *target) return true;
      if (++settledSinceCheck == kCancelCheckInterval) {
        settledSinceCheck = 0;
        if (cancel && cancel->load()) return false;
      }
      relaxNeighbours(offset, entry);
    }
    return true;
  }

  struct Entry {
    double cost = std::numeric_limits<double>::infinity();
    std::size_t parent = 0;
    double lengthMm = 0;
    bool settled = false;
  };

  const std::vector<std::size_t>& settled() const { return settled_; }
  const Entry* entryOf(std::size_t offset) const {
    const auto found = tentative_.find(offset);
    return found == tentative_.end() || !found->second.settled ? nullptr : &found->second;
  }

 private:
  void relaxNeighbours(std::size_t offset, const Entry& from) {
    const glm::ivec3 voxel = field_.voxelOf(offset);
    const double fromCost = from.cost, fromLength = from.lengthMm;
    for (const Neighbour& neighbour : neighbours_) {
      const glm::ivec3 next = voxel + neighbour.step;
      const float wall = field_.wallDistanceMm(next);
      if (wall <= 0 || wall < minWallMm_) continue;
      const std::size_t nextOffset = field_.offsetOf(next);
      const double cost = fromCost + neighbour.lengthMm * costPerMm(wall);
      Entry& entry = tentative_[nextOffset];
      if (entry.settled || cost >= entry.cost) continue;
      entry = {cost, offset, fromLength + neighbour.lengthMm, false};
      queue_.push({cost, nextOffset});
    }
  }

  using Queued = std::pair<double, std::size_t>;
  const LumenField& field_;
  double minWallMm_;
  std::array<Neighbour, 26> neighbours_;
  std::unordered_map<std::size_t, Entry> tentative_;
  std::priority_queue<Queued, std::vector<Queued>, std::greater<>> queue_;
  std::vector<std::size_t> settled_;
};

}  // namespace

std::optional<std::vector<glm::ivec3>> cheapestLumenPath(const LumenField& field, glm::ivec3 from,
                                                         glm::ivec3 to,
                                                         const std::atomic<bool>* cancel) {
  if (!field.isLumen(from) || !field.isLumen(to)) return std::nullopt;
  Dijkstra dijkstra(field, 0.0);
  const std::size_t target = field.offsetOf(to);
  if (!dijkstra.run(from, target, cancel) || !dijkstra.entryOf(target)) return std::nullopt;
  std::vector<glm::ivec3> path;
  for (std::size_t offset = target;;) {
    path.push_back(field.voxelOf(offset));
    const std::size_t parent = dijkstra.entryOf(offset)->parent;
    if (parent == offset) break;
    offset = parent;
  }
  std::reverse(path.begin(), path.end());
  return path;
}

LumenTree::LumenTree(const LumenField& field, glm::ivec3 root, double minWallDistanceMm,
                     const std::atomic<bool>* cancel)
    : field_(&field) {
  if (!field.isLumen(root)) return;
  Dijkstra dijkstra(field, minWallDistanceMm);
  if (!dijkstra.run(root, std::nullopt, cancel)) {
    cancelled_ = true;
    return;
  }
  nodes_.reserve(dijkstra.settled().size());
  nodeOfOffset_.reserve(dijkstra.settled().size());
  for (std::size_t offset : dijkstra.settled()) {
    const auto* entry = dijkstra.entryOf(offset);
    // Parents settle before their children, so their node index is known.
    const std::size_t parent = entry->parent == offset ? nodes_.size() : nodeOfOffset_.at(entry->parent);
    nodeOfOffset_.emplace(offset, nodes_.size());
    nodes_.push_back({offset, parent, entry->lengthMm});
  }
}

std::optional<std::size_t> LumenTree::nodeOf(std::size_t offset) const {
  const auto found = nodeOfOffset_.find(offset);
  if (found == nodeOfOffset_.end()) return std::nullopt;
  return found->second;
}

std::vector<glm::ivec3> LumenTree::pathTo(std::size_t node) const {
  std::vector<glm::ivec3> path;
  for (;;) {
    path.push_back(field_->voxelOf(nodes_[node].offset));
    if (nodes_[node].parent == node) break;
    node = nodes_[node].parent;
  }
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace angio
