#pragma once
// The accelerated raycaster: the reference's samples, minus those provably transparent.
// Empty-space skipping by slice tiles and tile groups (core/slice_tiles.h) walked through per-view
// ray templates (core/ray_templates.h), each row group by group in front-to-back order so a
// group's voxels are read from the cache by all rays through it; row bundles: consecutive rows
// that read the same voxels (same cell or nearest voxel along the rotation axis) walk each column
// together, so a cell's corners, transparency and gradients serve all of them (at the high level
// several rows share a slice pair); cell transparency and the cell's gradients cached per ray
// (core/ray_samplers.h); early ray termination; bundles in parallel (oneTBB, dynamic balance).
// With the trilinear or mean filter, DVR and MIP (not pre-integrated; labels hidden or with TFs of
// their own are fine, and DVR's VesselGlyph regions unless labels have TFs of their own) reconstruct
// eight samples of a ray at once in SIMD lanes, for every row of a bundle (core/sample_batch.h);
// DVR classifies them there (and, with
// the trilinear filter, shades them there from the cells' central differences) and composites only
// the visible ones, MIP takes their maximum. MIP starts each ray's maximum at the largest density
// its window shows black and ends a ray once it shows white.
// Voxels are read from the flat Volume or, with FastRenderOptions::blocks, from the blocked volume
// (core/voxel_grid.h), which gives the same image where blocksServe says so.
// The view's clipping (crop box, clip plane, slab: core/clip_interval.h) gives each lane the
// reference's sample range: it starts at its first sample and is finished after its last.
// Every evaluated sample uses the reference's operations (core/compositing.h), so the image is the
// reference's for every filter, mode, axis and angle, up to float rounding: the compiler may fuse
// a multiply and an add (-ffp-contract) in one inlined path and not in the other.
#include <atomic>
#include <cstdint>
#include <vector>

#include "core/blocked_volume.h"
#include "core/compositing.h"
#include "core/image.h"
#include "core/ray_profile.h"
#include "core/render_params.h"
#include "core/slice_tiles.h"
#include "core/tile_classification.h"
#include "core/transfer_function.h"
#include "core/volume.h"

namespace angio {

// Every switch exists to measure what a technique buys (`angioray bench`); the image is the same.
struct FastRenderOptions {
  bool skipEmpty = true;   // off: every sample evaluated, whatever the three below say
  bool skipGroups = true;  // the coarse level: 32^2-voxel tile groups no ray can see in this row
  bool skipTiles = true;   // the fine level: 8^2-voxel tiles
  bool skipCells = true;   // trilinear cells whose 8 corners the TF hides (or, MIP, not above the
                           // ray's maximum), and the leaps over their remaining samples; used
                           // only where samples are dense (osd < 0.75), where it pays
  // Rows that read the same voxels rendered in one pass (row bundles, core/fast_raycaster.cpp).
  bool shareRows = true;
  // Trilinear and mean, plain DVR: eight samples of a ray reconstructed and classified at once in
  // SIMD lanes (core/sample_batch.h); their samples in hidden cells are classified, not leapt over.
  bool batchSamples = true;
  const std::atomic<bool>* cancel = nullptr;  // checked per template column and per group of a row
  // Optional: an earlier frame whose pixel memory the new frame takes over (it is left empty).
  // Fresh memory for a frame costs page faults (the kernel clears every new page). A cancelled
  // frame's unrendered rows are then undefined.
  Image* recycle = nullptr;
  // Optional: incremented as each image row is finished (the GUI's progress bar), from 0.
  std::atomic<int>* rowsDone = nullptr;
  // Count where the samples go (FastRenderStats::profile), for plain DVR frames; a separately
  // compiled path, so frames without it pay nothing.
  bool profile = false;
  // Optional: render only the pixels whose entry is non-zero (row-major, the view's width x height;
  // core/image_refinement.h); the others keep the values of `recycle`'s image, which must then be
  // of the frame's size. Rows without such a pixel cost nothing, columns without one nearly nothing.
  const std::vector<std::uint8_t>* pixels = nullptr;
  // Optional: read the voxels from these blocks (thesis sec. 4.2.1, core/blocked_volume.h) instead
  // of the Volume's, which then gives the geometry only and need not hold voxels. Only where
  // blocksServe says the image is the same; renderFast throws std::logic_error otherwise.
  const BlockedVolume* blocks = nullptr;
};

struct FastRenderStats {
  std::uint64_t samples = 0;  // samples in tiles not skipped (clipped regions included)
  double templateMs = 0;      // building the ray templates for this view
  bool cancelled = false;
  bool profiled = false;  // FastRenderOptions::profile was set and the frame is plain DVR
  RayProfile profile;
};

// Whether a frame rendered from `blocked` is the flat volume's frame, bit for bit: its dummy block
// stands for background voxels whose true densities are only known to lie below the background
// threshold. True for DVR when every TF the frame may use for unlabelled voxels is transparent
// there, and for MIP when the window shows every density below it as black; never with
// pre-integration (a segment's opacity depends on where along it the density crosses the TF).
bool blocksServe(const BlockedVolume& blocked, const RegionTables& tables, const RenderParams& params);

// `classification` must be of tiles built for params.axis and made from `tables`' TFs (throws
// std::logic_error otherwise). With regions, VesselGlyph: a TF per region of each ray
// (core/compositing.h).
Image renderFast(const Volume& volume, const TileClassification& classification,
                 const RegionTables& tables, const RenderParams& params,
                 const FastRenderOptions& options = {}, FastRenderStats* stats = nullptr);
// Plain DVR/MIP with one TF.
Image renderFast(const Volume& volume, const TileClassification& classification, const TfTable& table,
                 const RenderParams& params, const FastRenderOptions& options = {},
                 FastRenderStats* stats = nullptr);

}  // namespace angio
