#pragma once
// Centerlines protect their lumen from bone removal: every voxel within the local radius + a margin
// of a path (a tapered capsule per segment) gets a flag bit.
#include <cstdint>
#include <vector>

#include "core/volume.h"
#include "vessel/centerline.h"

namespace angio::segment {

// Sets `bit` in flags[n] (one byte per voxel of volume) for the voxels within radius + marginMm of
// the centerlines (either frame; radius 0 = unknown protects the margin only).
void markLumen(std::vector<std::uint8_t>& flags, std::uint8_t bit, const Volume& volume,
               const Centerlines& centerlines, double marginMm);

}  // namespace angio::segment
