#pragma once
// The oracle of adaptive sampling (seed 003, sec. 3 and 4): for any point, a distance within which
// samples may be skipped. Like the seed's "distance to the nearest voxel whose opacity gradient
// exceeds a threshold", from what the TF and the volume already tell:
//  - the volume in blocks of kBlock^3 voxels, each with its density range (as the labels read);
//  - a block is an edge when the TF changes over that range by more than the tolerance: the total
//    variation of the opacity per voxel unit, or of the opacity-weighted colour, between the range's
//    ends (an O(1) bound of max - min from prefix sums, never below it);
//  - a point's distance is the Chebyshev distance in blocks to the nearest edge block, less one
//    block (a sample's filter reaches a voxel into the next block), in voxel units.
// So hidden space far from visible material and smooth material (a faint, homogeneous organ) give
// long distances; everything within a block of an opacity edge gives 0.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/label_tables.h"
#include "core/transfer_function.h"
#include "core/volume.h"

namespace angio {

class SamplingOracle {
 public:
  static constexpr int kBlock = 4;
  // The farthest distance told apart: 254 blocks (a byte per block), more than any skip asks for
  // at the levels' sampling distances (2^7 samples of 3 voxels).
  static constexpr double kLongestReach = 254.0 * kBlock;

  SamplingOracle() = default;
  // Distances beyond `reach` voxel units (at most kLongestReach) are not told apart: reported as
  // at least `reach`.
  SamplingOracle(const Volume& volume, const TfTable& table, const MaskedDensity& read, double tolerance,
                 double reach);

  // A lower bound of the distance (voxel units, i.e. index space) from q (continuous voxel
  // coordinates; outside the volume: its nearest block) to the nearest edge block's voxels.
  float distanceAt(const glm::dvec3& q) const {
    const glm::ivec3 b =
        glm::clamp(glm::ivec3(glm::floor(q / double(kBlock))), glm::ivec3(0), blocks_ - 1);
    return distanceOfBlocks_[distanceInBlocks_[(std::size_t(b.z) * blocks_.y + b.y) * blocks_.x + b.x]];
  }
  glm::ivec3 blocks() const { return blocks_; }
  std::size_t edgeBlockCount() const { return edgeBlocks_; }

 private:
  glm::ivec3 blocks_{0};
  std::vector<std::uint8_t> distanceInBlocks_;  // Chebyshev, capped
  std::vector<float> distanceOfBlocks_;         // voxel units by distance in blocks
  std::size_t edgeBlocks_ = 0;
};

}  // namespace angio
