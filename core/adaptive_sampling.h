#pragma once
// Adaptive sampling in three dimensions (seed 003; an approximation of the rendering model,
// "Approximations"). The samples k of all rays lie on the planes t = k delta (the seed's slices);
// an oracle (core/sampling_oracle.h) gives each sample a distance d within which nothing changes
// much, in units of u = max(isd, osd).
//  - Along rays (sec. 3.1): on slice i (counted from an aligned start) with l_slice = the trailing
//    zeros of i, at most l_max, a ray that stored d >= 2^(l_slice + 1) skips the sample.
//  - Across the image (sec. 3.2): an image pyramid of l_max + 1 levels holds density, shading
//    factor and d per pixel; level l's pixel x sits at level 0's 2^l (x + 1/2) - 1/2. Level l_max is
//    always sampled; finer pixels are synthesised from the next coarser level by biquadratic
//    B-spline subdivision (weights 3/4, 1/4 per axis) and sampled only where d < 2^(l + 1).
//  - Level 0's pixels composite front to back where they were updated (sec. 3.3, Fig. 6), the
//    segment since their last update pre-integrated over its length (core/preintegration.h),
//    shaded by the mean of its ends' shading factors.
// The seed walks every pixel of every slice (a GPU's early depth test drops the skipped ones); here
// each level keeps its pixels in buckets by the power of two they wait for, so a slice visits only
// the pixels it updates. The image is made in bands of rows, each with the coarser levels' rows it
// synthesises from, so bands are independent (and the image the same for any thread count).
// With 0 levels it is the pre-integrated exact image. Plain DVR with one TF (hidden labels read 0);
// no VesselGlyph regions or labels with their own TF; MIP renders by samples.
#include <atomic>
#include <cstdint>
#include <string>

#include "core/compositing.h"
#include "core/image.h"
#include "core/render_params.h"
#include "core/sampling_oracle.h"
#include "core/volume.h"

namespace angio {

struct AdaptiveSamplingStats {
  std::uint64_t samples = 0;      // volume samples: density, gradient and oracle, any level
  std::uint64_t synthesised = 0;  // pixels synthesised from a coarser level
  std::uint64_t segments = 0;     // segments composited at level 0
  bool cancelled = false;         // `cancel` was set: bands not yet begun are left black
};

// Why `params` cannot be sampled adaptively (not enabled, MIP, a sampling problem), or "".
std::string adaptiveSamplingProblem(const RenderParams& params);

// The oracle of the TF that adaptive sampling renders with (`tables.outside`) and the labels'
// mask, for the settings' tolerance; it serves every level and view of them.
SamplingOracle makeSamplingOracle(const Volume& volume, const RegionTables& tables, double tolerance);

// The image of `params` with params.sampling.adaptiveSampling; throws std::invalid_argument where
// adaptiveSamplingProblem says why not, for VesselGlyph regions, or for labels with their own TF.
// `cancel`, if set, is checked between slices; `rowsDone`, if set, counts finished rows.
Image renderAdaptiveSampling(const Volume& volume, const RegionTables& tables,
                             const SamplingOracle& oracle, const RenderParams& params,
                             AdaptiveSamplingStats* stats = nullptr,
                             const std::atomic<bool>* cancel = nullptr,
                             std::atomic<int>* rowsDone = nullptr);

}  // namespace angio
