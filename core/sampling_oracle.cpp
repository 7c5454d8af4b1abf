#include "core/sampling_oracle.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace angio {

namespace {

// Prefix sums of |change| between neighbouring TF entries: of the opacity per voxel unit, and of the
// largest channel of the opacity-weighted colour. The TF's variation over densities [lo, hi] is
// at most variation[hi] - variation[lo].
std::array<double, kDensityLevels> totalVariation(const TfTable& table) {
  std::array<double, kDensityLevels> variation{};
  for (int d = 1; d < kDensityLevels; ++d) {
    const glm::vec4 a = table.rgba[d - 1], b = table.rgba[d];
    const glm::vec3 change = glm::abs(glm::vec3(b) * b.a - glm::vec3(a) * a.a);
    const double step =
        std::max({double(std::abs(b.a - a.a)), double(change.r), double(change.g), double(change.b)});
    variation[d] = variation[d - 1] + step;
  }
  return variation;
}

struct BlockRange {
  std::uint16_t lo = kDensityLevels, hi = 0;
};

// Per block, the range of its voxels' densities as `read` reads them; one task per layer of blocks.
std::vector<BlockRange> blockRanges(const Volume& volume, const MaskedDensity& read, glm::ivec3 blocks) {
  constexpr int B = SamplingOracle::kBlock;
  std::vector<BlockRange> ranges(std::size_t(blocks.x) * blocks.y * blocks.z);
  tbb::parallel_for(0, blocks.z, [&](int bz) {
    BlockRange* layer = ranges.data() + std::size_t(bz) * blocks.y * blocks.x;
    for (int z = bz * B; z < std::min(volume.dims.z, bz * B + B); ++z)
      for (int y = 0; y < volume.dims.y; ++y) {
        BlockRange* row = layer + std::size_t(y / B) * blocks.x;
        const Voxel* voxel = volume.voxels.data() + volume.indexOf(0, y, z);
        for (int x = 0; x < volume.dims.x; ++x) {
          const auto d = std::uint16_t(densityOf(Voxel(read(voxel[x]))));
          BlockRange& r = row[x / B];
          r.lo = std::min(r.lo, d);
          r.hi = std::max(r.hi, d);
        }
      }
  });
  return ranges;
}

// Chebyshev distance (in blocks, capped at `cap`) to the nearest block with distance 0: the
// two-pass chamfer with unit weights over the 26 neighbours, which is exact for this metric.
void chebyshevDistance(std::vector<std::uint8_t>& distance, glm::ivec3 n, int cap) {
  const auto at = [&](int x, int y, int z) -> std::uint8_t& {
    return distance[(std::size_t(z) * n.y + y) * n.x + x];
  };
  const auto relax = [&](int x, int y, int z, int sign) {
    int best = at(x, y, z);
    for (int dz = -1; dz <= 0; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          // The 13 neighbours before (x, y, z) in the pass's order.
          if (dz == 0 && (dy > 0 || (dy == 0 && dx >= 0))) continue;
          const int nx = x + sign * dx, ny = y + sign * dy, nz = z + sign * dz;
          if (nx < 0 || ny < 0 || nz < 0 || nx >= n.x || ny >= n.y || nz >= n.z) continue;
          best = std::min(best, at(nx, ny, nz) + 1);
        }
    at(x, y, z) = std::uint8_t(std::min(best, cap));
  };
  for (int z = 0; z < n.z; ++z)
    for (int y = 0; y < n.y; ++y)
      for (int x = 0; x < n.x; ++x) relax(x, y, z, 1);
  for (int z = n.z - 1; z >= 0; --z)
    for (int y = n.y - 1; y >= 0; --y)
      for (int x = n.x - 1; x >= 0; --x) relax(x, y, z, -1);
}

}  // namespace

SamplingOracle::SamplingOracle(const Volume& volume, const TfTable& table, const MaskedDensity& read,
                               double tolerance, double reach) {
  blocks_ = (volume.dims + kBlock - 1) / kBlock;
  const std::vector<BlockRange> ranges = blockRanges(volume, read, blocks_);
  const std::array<double, kDensityLevels> variation = totalVariation(table);
  // Block distance n means at least (n - 1) blocks of voxels between; n = cap stands for "far".
  const int cap = std::clamp(int(std::ceil(reach / kBlock)) + 1, 1, 255);
  distanceInBlocks_.resize(ranges.size());
  for (std::size_t b = 0; b < ranges.size(); ++b) {
    const BlockRange r = ranges[b];
    const bool edge = r.lo <= r.hi && variation[r.hi] - variation[r.lo] > tolerance;
    distanceInBlocks_[b] = edge ? 0 : std::uint8_t(cap);
    edgeBlocks_ += edge;
  }
  chebyshevDistance(distanceInBlocks_, blocks_, cap);
  distanceOfBlocks_.resize(cap + 1);
  for (int n = 0; n <= cap; ++n) distanceOfBlocks_[n] = float(std::max(0, n - 1) * kBlock);
}

}  // namespace angio
