#pragma once
// Voxel encoding of the rendering model: 12-bit density d = clamp(round(HU) + 1024, 0, 4095)
// in the low bits, 4-bit segmentation label in the high bits (0 = none).
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace angio {

using Voxel = std::uint16_t;

constexpr int kDensityLevels = 4096;
constexpr int kHuOffset = 1024;  // density 0 is -1024 HU
constexpr int kMaxLabel = 15;
constexpr int kLabelCount = kMaxLabel + 1;  // label 0 (none) included

constexpr int densityOf(Voxel v) { return v & 0x0FFF; }
constexpr int labelOf(Voxel v) { return v >> 12; }
constexpr Voxel withLabel(Voxel v, int label) { return Voxel(densityOf(v) | (label << 12)); }
constexpr double huOfDensity(double d) { return d - kHuOffset; }

// A voxel's density as every voxel reads when no label is hidden.
struct PlainDensity {
  int operator()(Voxel v) const { return densityOf(v); }
};

inline int densityOfHu(double hu) {
  const double d = std::round(hu) + kHuOffset;
  return static_cast<int>(std::clamp(d, 0.0, double(kDensityLevels - 1)));
}

inline Voxel encodeVoxel(double hu, int label = 0) {
  return static_cast<Voxel>(densityOfHu(hu) | (std::clamp(label, 0, kMaxLabel) << 12));
}

}  // namespace angio
