#pragma once
// Error-controlled adaptive integration of each ray (seed 000, sec. 4.3; an approximation of the
// rendering model, "Approximations"): instead of samples every osd, the ray's emission-absorption
// integral is approximated on intervals that start at `initialStep` voxel units and are bisected
// where the trapezoidal and Simpson rules disagree most:
//   T(I) = h/4 (q_l + 2 q_m e^{-h/4 (k_l + k_m)} + q_r e^{-h/4 (k_l + 2 k_m + k_r)})      (4.11)
//   S(I) = h/6 (q_l + 4 q_m e^{-h/4 (k_l + k_m)} + q_r e^{-h/6 (k_l + 4 k_m + k_r)})      (4.12)
// at the interval's ends and midpoint, with extinction k = -ln(1 - a) per voxel unit from the TF's
// opacity a and emission q = rgb s k (s the shading factor): the continuous model that the
// rendering model's sum converges to as osd -> 0. The local error |T - S| is weighted by the
// transparency in front of the interval (4.13); each pass bisects the intervals whose local error
// is at least the largest extrapolated one, e_loc^2 / e_loc(parent) (4.7, 4.8), and the passes stop
// once the whole ray's Simpson sum changed by at most c_tol of itself (4.9, 4.10). For the first
// discretisation, which has no coarser one, the change is taken as |T(G) - S(G)|: a ray whose
// integrand the initial intervals already resolve (a constant medium) is not refined at all.
// Nodes are every initialStep / 2 apart at first, so nothing thicker than that is missed; thinner
// features may be, as the seed says of every adaptive scheme. Plain DVR and labels; no VesselGlyph
// regions, no MIP (render/frame_renderer renders MIP by samples whatever the sampling says). No
// empty-space skipping: every ray is integrated over its whole clipped domain, up to early ray
// termination.
#include <atomic>
#include <cstdint>
#include <string>

#include "core/compositing.h"
#include "core/image.h"
#include "core/render_params.h"
#include "core/volume.h"

namespace angio {

struct AdaptiveIntegrationStats {
  std::uint64_t nodes = 0;   // samples evaluated (density, TF, gradient where visible)
  std::uint64_t passes = 0;  // refinement passes summed over the rays
  bool cancelled = false;    // `cancel` was set: rows not yet begun are left black
};

// Why `params` cannot be integrated adaptively (not enabled, MIP), or "".
std::string adaptiveIntegrationProblem(const RenderParams& params);

// The image of `params` with params.sampling.adaptive; throws std::invalid_argument where
// adaptiveIntegrationProblem says why not, or for VesselGlyph regions in `tables`.
// `cancel`, if set, is checked before each row; `rowsDone`, if set, is incremented after each.
Image renderAdaptive(const Volume& volume, const RegionTables& tables, const RenderParams& params,
                     AdaptiveIntegrationStats* stats = nullptr,
                     const std::atomic<bool>* cancel = nullptr, std::atomic<int>* rowsDone = nullptr);

}  // namespace angio
