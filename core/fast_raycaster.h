#pragma once
// The accelerated raycaster: the reference's samples, minus those provably transparent.
// Empty-space skipping by slice tiles (core/slice_tiles.h) walked through per-view ray templates
// (core/ray_templates.h), early ray termination, rows in parallel (oneTBB, dynamic balance).
// Every evaluated sample uses the reference's arithmetic (core/compositing.h), so the image is the
// reference's, bit for bit, for every filter, mode, axis and angle.
#include <atomic>
#include <cstdint>
#include <vector>

#include "core/compositing.h"
#include "core/image.h"
#include "core/render_params.h"
#include "core/slice_tiles.h"
#include "core/transfer_function.h"
#include "core/volume.h"

namespace angio {

struct FastRenderOptions {
  bool skipEmpty = true;                      // off: every sample evaluated (for measuring)
  const std::atomic<bool>* cancel = nullptr;  // checked every 64 pixels; set -> returns early
};

struct FastRenderStats {
  std::uint64_t samples = 0;     // samples in tiles not skipped (clipped regions included)
  double templateMs = 0;         // building the ray templates for this view
  bool cancelled = false;
};

// `tiles` must be built for params.axis; `visibleTiles` = classifyTiles(tiles, table).
Image renderFast(const Volume& volume, const SliceTiles& tiles,
                 const std::vector<std::uint8_t>& visibleTiles, const TfTable& table,
                 const RenderParams& params, const FastRenderOptions& options = {},
                 FastRenderStats* stats = nullptr);

// VesselGlyph: a TF per region of each ray (core/compositing.h). `visibleTiles` must be
// classifyTiles(tiles, tables): a tile is visible if any region's TF shows a density in it.
Image renderFast(const Volume& volume, const SliceTiles& tiles,
                 const std::vector<std::uint8_t>& visibleTiles, const RegionTables& tables,
                 const RenderParams& params, const FastRenderOptions& options = {},
                 FastRenderStats* stats = nullptr);
std::vector<std::uint8_t> classifyTiles(const SliceTiles& tiles, const RegionTables& tables);

}  // namespace angio
