#pragma once
// Resampling a CPR layout (vessel/cpr_layout.h): the HU value at every pixel's point.
//
// Two ways, the same points:
// - trilinear: each point reconstructed in 3-D with the rendering model's trilinear filter
//   (core/volume_sampling.h), the reference the raycasters use. The default.
// - opencvRemap: the points of a span grouped by the pair of k-slices they fall between; each
//   group is resampled in both slices by cv::remap (per-row maps, INTER_LINEAR) and the two
//   results blended by the fraction along k. cv::remap quantises the position inside a cell to
//   1/32 of a voxel (INTER_BITS = 5) even for float maps, so at strong edges (lumen to wall,
//   ~1000 HU per voxel) it is off by up to ~1000/64 HU; tests/vessel/cpr_test.cpp measures it.
//   Kept for that comparison, not used by default.
#include <optional>
#include <string>
#include <vector>

#include "core/volume.h"
#include "vessel/cpr_layout.h"

namespace angio {

enum class CprResampler { trilinear, opencvRemap };

const char* toString(CprResampler resampler);
std::optional<CprResampler> parseCprResampler(const std::string& text);

// The HU at a point (mm, volume frame) by the trilinear filter: the trilinear resampler's value
// at a pixel showing that point. The volume must have voxels.
float trilinearHu(const Volume& volume, glm::dvec3 pointMm);

// HU per pixel, row-major (layout.width x layout.height), NaN where no span samples.
std::vector<float> resampleCpr(const Volume& volume, const CprLayout& layout,
                               CprResampler resampler = CprResampler::trilinear);

}  // namespace angio
