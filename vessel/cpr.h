#pragma once
// Curved planar reformation (thesis sec. 1.3.2, 5.2.2; Kanitsar et al., IEEE Vis 2002):
// the entry point. The geometry of the three projections is in vessel/cpr_layout.h, the
// resampling in vessel/cpr_resample.h, the display (window/level or TF, marker, ruler) in
// vessel/cpr_display.h.
//
//   const Centerlines inVolume = toVolumeFrame(loadCenterlines(file), volume);
//   const ViewGeometry view = cprView(volume, Axis::k, angleDeg, 0.5);
//   const Cpr cpr = computeCpr(volume, selectPaths(inVolume, "all"), view,
//   {CprMode::straightened}); exportImage(displayCpr(cpr.layout, cpr.hu, {}), "cpr.png",
//   cprMetadata(cpr.layout, description));
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/render_params.h"
#include "core/view_geometry.h"
#include "core/volume.h"
#include "vessel/centerline.h"
#include "vessel/cpr_display.h"
#include "vessel/cpr_layout.h"
#include "vessel/cpr_resample.h"

namespace angio {

struct Cpr {
  CprLayout layout;
  std::vector<float> hu;  // row-major, NaN = not sampled

  float huAt(int x, int y) const { return hu[std::size_t(y) * layout.width + x]; }
};

// What a CPR pixel shows (for a cursor: arc length, HU, and the point to mark on the DVR image).
struct CprPick {
  glm::dvec3 pointMm{0.0};  // volume frame
  float hu = 0;
  int path = 0;      // index into the paths given to computeCpr
  double arcMm = 0;  // arc length of the centerline point this pixel's line passes through
};
// nullopt where the pixel is outside the image or not sampled.
std::optional<CprPick> pickCpr(const Cpr& cpr, int x, int y);

// The view a CPR is laid out in: the rendering model's view about `axis` at `angleDeg` with
// pixels of `pixelMm` (isd = pixelMm / u), so a projected CPR registers with the DVR image
// rendered at that isd.
ViewGeometry cprView(const Volume& volume, Axis axis, double angleDeg, double pixelMm);

// paths in the volume frame. Throws std::invalid_argument as layoutCpr does.
Cpr computeCpr(const Volume& volume, const std::vector<CenterlinePath>& paths, const ViewGeometry& view,
               const CprSettings& settings, CprResampler resampler = CprResampler::trilinear);

struct CprDescription {
  std::string dataset;
  std::string centerlines;
  std::vector<std::string> pathNames;  // in the order given to computeCpr
  Axis axis = Axis::k;
  double angleDeg = 0;
  std::string display;  // e.g. "window 800 level 250" or "tf CTA vessels"
  CprResampler resampler = CprResampler::trilinear;
};

// Key/value metadata for the exported image (io/image_export.h's ImageMetadata): how it was made
// and how to measure on it (mm per pixel, what rows and columns mean).
std::map<std::string, std::string> cprMetadata(const CprLayout& layout,
                                               const CprDescription& description);

}  // namespace angio
