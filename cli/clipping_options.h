#pragma once
// The crop box, clip plane and thick slab options of `angioray render` (core/view_clipping.h) and
// their translation into the render's clipping.
#include <optional>
#include <string>

#include "core/view_clipping.h"

namespace CLI {
class App;
}

namespace angio {

// The options as given (lists of numbers, parsed by clippingFrom).
struct ClippingCliOptions {
  std::optional<std::string> crop;   // "i0,i1,j0,j1,k0,k1", mm of the volume frame
  std::optional<std::string> clip;   // "px,py,pz,nx,ny,nz", mm of the volume frame
  std::optional<double> clipFacing;  // offset (mm) of a plane facing the viewer
  std::optional<std::string> slab;   // "offset_mm,thickness_mm"
};

// Adds --crop, --clip, --clip-facing (excludes --clip) and --slab.
void addClippingOptions(CLI::App& render, ClippingCliOptions& options);

// Throws std::invalid_argument with one line naming the flag for a wrong count of numbers, a
// non-finite number, an empty crop box, a zero normal or a slab not thicker than 0.
ViewClipping clippingFrom(const ClippingCliOptions& options);

}  // namespace angio
