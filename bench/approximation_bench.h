#pragma once
// The approximations of the rendering model measured against its exact images (issue of the
// seeds' adaptive techniques): for each level, frames at the level's own osd and at larger ones,
// exact and pre-integrated, each timed (median, min, max over the angles), its samples counted and
// its image compared (PSNR over the 8-bit output) with the exact image at the level's osd and with
// the converged one (exact at a quarter of the level's osd: what a finer osd tends to). Image-plane
// refinement rows (core/image_refinement.h) refine the level's exact frames. Adaptive
// integration rows (seed 000 sec. 4.3) use the level's filter and isd and no osd. The angles are the
// frame bench's plus 15 degrees, so that no view is axis-aligned.
#include <string>
#include <vector>

#include "core/image_refinement.h"
#include "core/render_params.h"
#include "core/transfer_function.h"
#include "core/volume.h"

namespace angio {

struct ApproximationSettings {
  int angles = 6;
  Axis axis = Axis::k;
  int threads = 0;                  // 0 = all cores
  std::vector<std::string> levels;  // names (bench/frame_bench.h benchLevels); empty = all
  std::vector<double> osdScales = {1, 1.5, 2, 3, 4};  // times the level's osd
  // Adaptive integration rows (core/adaptive_integration.h) per level: these c_tol with these
  // initial steps (voxels), each pair a row.
  std::vector<AdaptiveIntegration> adaptive = {
      {0.01, 4.0, 0.125}, {0.01, 2.0, 0.125}, {0.001, 1.0, 0.125}};
  // Adaptive sampling rows (core/adaptive_sampling.h) per level: these levels and oracle
  // tolerances, each a row; the oracle is made ahead (its time is reported apart, once per TF).
  std::vector<AdaptiveSampling> adaptiveSampling = {{3, 3, 0.02}, {3, 6, 0.02}, {3, 6, 0.1}};
  // Image-plane refinement rows (core/image_refinement.h) per level: these levels and tolerances.
  std::vector<ImageRefinement> refinement = {{2, 0.02}, {2, 0.1}, {3, 0.05}, {4, 0.3}};
};

struct ApproximationRow {
  std::string level;
  double osd = 0;
  std::string technique;  // "post", "pre-integrated", "adaptive c_tol 0.01, h0 4"
  double medianMs = 0, minMs = 0, maxMs = 0;
  double medianSamples = 0;    // samples in tiles not skipped, per frame
  double psnrLevelDb = 0;      // median over the angles, against the exact image at the level's osd
  double minPsnrLevelDb = 0;   // the worst angle
  double psnrConvergedDb = 0;  // median, against the exact image at a quarter of the level's osd
  int frames = 0;
  double setupMs = 0;  // the first frame, which makes what later frames reuse (the oracle)
};

std::vector<ApproximationRow> runApproximationBench(const Volume& volume, const TransferFunction& tf,
                                                    const ApproximationSettings& settings);

std::string formatApproximationBench(const std::vector<ApproximationRow>& rows);

}  // namespace angio
