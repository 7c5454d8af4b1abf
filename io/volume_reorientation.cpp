#include "io/volume_reorientation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace angio {

namespace {

// Angle (degrees) between unit vector `axis` and LPS axis `lps`; atan2 stays accurate near 0.
double degreesOff(const glm::dvec3& axis, int lps) {
  const double along = std::abs(axis[lps]);
  const double across = std::sqrt(std::max(0.0, glm::dot(axis, axis) - along * along));
  return glm::degrees(std::atan2(across, along));
}

glm::dmat3 unitColumns(const glm::dmat3& direction) {
  glm::dmat3 unit;
  for (int axis = 0; axis < 3; ++axis) {
    const double length = glm::length(direction[axis]);
    if (!std::isfinite(length) || length < 1e-9)
      throw std::invalid_argument("zero or non-finite direction vector");
    unit[axis] = direction[axis] / length;
  }
  if (std::abs(glm::determinant(unit)) < 0.1)
    throw std::invalid_argument("direction vectors are (nearly) parallel");
  return unit;
}

}  // namespace

bool Reorientation::movesVoxels() const {
  return sourceAxis != std::array<int, 3>{0, 1, 2} || flipped[0] || flipped[1] || flipped[2];
}

Reorientation planReorientation(const glm::dmat3& direction) {
  const glm::dmat3 unit = unitColumns(direction);
  Reorientation plan;
  std::array<bool, 3> storedTaken{}, lpsTaken{};
  for (int round = 0; round < 3; ++round) {
    int bestStored = -1, bestLps = -1;
    double bestCosine = -1.0;
    for (int stored = 0; stored < 3; ++stored) {
      for (int lps = 0; lps < 3; ++lps) {
        if (storedTaken[stored] || lpsTaken[lps]) continue;
        const double cosine = std::abs(unit[stored][lps]);
        if (cosine > bestCosine) bestCosine = cosine, bestStored = stored, bestLps = lps;
      }
    }
    storedTaken[bestStored] = lpsTaken[bestLps] = true;
    plan.sourceAxis[bestLps] = bestStored;
    plan.flipped[bestLps] = unit[bestStored][bestLps] < 0.0;
    plan.obliqueDegrees = std::max(plan.obliqueDegrees, degreesOff(unit[bestStored], bestLps));
  }
  return plan;
}

VolumeGeometry reorientedGeometry(const VolumeGeometry& stored, const Reorientation& plan) {
  VolumeGeometry out;
  glm::dvec3 firstVoxel(0.0);  // stored index of the new voxel (0, 0, 0)
  for (int axis = 0; axis < 3; ++axis) {
    const int from = plan.sourceAxis[axis];
    out.dims[axis] = stored.dims[from];
    out.spacing[axis] = stored.spacing[from];
    out.direction[axis] = plan.flipped[axis] ? -stored.direction[from] : stored.direction[from];
    if (plan.flipped[axis]) firstVoxel[from] = stored.dims[from] - 1;
  }
  out.origin = stored.origin + stored.direction * (firstVoxel * stored.spacing);
  // Headers store cosines in float precision; below 1e-6 (0.5 um over 500 mm) call it aligned.
  double largestResidual = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      largestResidual = std::max(largestResidual, std::abs(out.direction[c][r] - (c == r ? 1.0 : 0.0)));
  if (largestResidual < 1e-6) out.direction = glm::dmat3(1.0);
  return out;
}

}  // namespace angio
