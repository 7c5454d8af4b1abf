#pragma once
// VesselGlyph's split of every ray into regions (thesis ch. 5.3.1): sorted, non-overlapping depth
// intervals labelled focus or context; depths not covered by any interval are "outside". Built per
// view by vessel/ from the centerlines; the raycaster only compares sample depths with the bounds,
// so core knows intervals per ray, never centerlines.
#include <cstdint>
#include <vector>

namespace angio {

enum class Region : std::uint8_t { outside = 0, focus = 1, context = 2 };

// Depths are t in mm along the ray p(t) = origin + t d of the rendering model (ViewGeometry):
// a sample at t belongs to the interval when begin <= t < end.
struct RegionInterval {
  float begin = 0;
  float end = 0;
  Region region = Region::focus;
};

struct RayRegions {
  int width = 0;  // the view's image size
  int height = 0;
  // Intervals of pixel (x, y), n = y * width + x: [rayBegin[n], rayBegin[n + 1]).
  std::vector<std::uint32_t> rayBegin;
  std::vector<RegionInterval> intervals;
};

}  // namespace angio
