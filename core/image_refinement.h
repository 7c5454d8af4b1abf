#pragma once
// Image-plane refinement: an approximation of the rendering model ("Approximations"), the image
// pyramid of seed 003 (sec. 3.2) driven by the rendered pixels instead of an oracle, in the manner
// of Levoy's adaptive refinement. Rays 2^levels apart are cast first (a lattice, plus the last
// column and row); then, level by level, each lattice cell whose four corner pixels agree within
// the tolerance (every channel's spread at most it) is filled by bilinear interpolation of its
// corners, and each other cell casts the rays at its edge midpoints and centre and is split in four
// for the next level. At the last level every pixel of a cell that disagrees is cast. Cast pixels
// are exact (the fast raycaster's); with tolerance 0 only cells of four equal corners are filled.
// What it can miss: a structure thinner than the lattice that passes between a cell's corners
// without touching one (a vessel narrower than 2^levels pixels crossing a cell diagonally).
#include <cstdint>
#include <functional>
#include <vector>

#include "core/compositing.h"
#include "core/fast_raycaster.h"
#include "core/image.h"
#include "core/render_params.h"
#include "core/tile_classification.h"
#include "core/volume.h"

namespace angio {

struct ImageRefinement {
  int levels = 2;           // rays 2^levels apart at first (at least 1)
  double tolerance = 0.02;  // per channel of the pixel (0..1): the corners' largest spread

  friend bool operator==(const ImageRefinement&, const ImageRefinement&) = default;
};

// Renders the pixels of `image` whose mask entry is non-zero (row-major, width x height), leaving
// the others as they are; returns false if cancelled.
using RenderPixels = std::function<bool(const std::vector<std::uint8_t>& mask, Image& image)>;

struct RefinementStats {
  std::uint64_t cast = 0;          // pixels rendered
  std::uint64_t interpolated = 0;  // pixels filled from their cells' corners (the rest)
  int passes = 0;                  // calls of the renderer
  bool cancelled = false;
};

// The refined image of width x height pixels, cast through `render`. (The part of renderRefined
// that knows nothing of volumes, for tests with analytic images.)
Image refineImage(int width, int height, const ImageRefinement& refinement, const RenderPixels& render,
                  RefinementStats* stats = nullptr);

// The fast raycaster's image of `params`, refined. FastRenderStats sum the passes; options.pixels
// must be unset.
Image renderRefined(const Volume& volume, const TileClassification& classification,
                    const RegionTables& tables, const RenderParams& params,
                    const ImageRefinement& refinement, const FastRenderOptions& options = {},
                    FastRenderStats* stats = nullptr, RefinementStats* refinementStats = nullptr);

}  // namespace angio
