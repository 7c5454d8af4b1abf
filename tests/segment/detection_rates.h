#pragma once
// Test reference: how well labels match a phantom's ground truth (phantom.h, groundTruthLabels).
// Lumen voxels are those within the ground-truth centerlines' radius (a union of spheres at the
// path points, 1 mm apart) that the ground truth leaves unlabelled (plaque over lumen is not lumen).
#include <cstdint>
#include <vector>

#include "core/labels.h"
#include "phantom/phantom.h"

namespace angio::test_support {

struct DetectionRates {
  std::size_t bone = 0, boneFound = 0;
  std::size_t table = 0, tableFound = 0;
  std::size_t lumen = 0, lumenAsBone = 0;
  std::size_t other = 0, otherAsBone = 0;  // neither bone nor lumen in the ground truth

  double boneFoundFraction() const { return double(boneFound) / double(bone); }
  double tableFoundFraction() const { return double(tableFound) / double(table); }
  double lumenAsBoneFraction() const { return double(lumenAsBone) / double(lumen); }
  double otherAsBoneFraction() const { return double(otherAsBone) / double(other); }
};

inline std::vector<bool> lumenVoxels(const Phantom& phantom) {
  const Volume& volume = phantom.volume;
  std::vector<bool> lumen(volume.voxelCount(), false);
  for (const CenterlinePath& path : phantom.centerlines.paths) {
    for (const CenterlinePoint& point : path.points) {
      const glm::dvec3 centre = physicalToIndex(volume, point.positionMm);
      const glm::dvec3 reach = point.radiusMm / volume.spacing;
      const glm::ivec3 lo = glm::max(glm::ivec3(glm::ceil(centre - reach)), glm::ivec3(0));
      const glm::ivec3 hi = glm::min(glm::ivec3(glm::floor(centre + reach)), volume.dims - 1);
      for (int k = lo.z; k <= hi.z; ++k)
        for (int j = lo.y; j <= hi.y; ++j)
          for (int i = lo.x; i <= hi.x; ++i) {
            const glm::dvec3 d = (glm::dvec3(i, j, k) - centre) * volume.spacing;
            if (glm::dot(d, d) <= point.radiusMm * point.radiusMm) lumen[volume.indexOf(i, j, k)] = true;
          }
    }
  }
  return lumen;
}

// phantom carries its ground truth in the label bits; labels are one per voxel.
inline DetectionRates detectionRates(const Phantom& phantom, const std::vector<std::uint8_t>& labels) {
  const std::vector<bool> lumen = lumenVoxels(phantom);
  DetectionRates rates;
  for (std::size_t n = 0; n < labels.size(); ++n) {
    const int truth = labelOf(phantom.volume.voxels[n]);
    const bool bone = labels[n] == kBoneLabel;
    if (truth == kBoneLabel) {
      ++rates.bone;
      rates.boneFound += bone;
    } else if (lumen[n] && truth == 0) {
      ++rates.lumen;
      rates.lumenAsBone += bone;
    } else {
      ++rates.other;
      rates.otherAsBone += bone;
    }
    if (truth == kTableLabel) {
      ++rates.table;
      rates.tableFound += labels[n] == kTableLabel;
    }
  }
  return rates;
}

}  // namespace angio::test_support
