#pragma once
// "Export rotation series": N views over an arc about the view's rotation axis, rendered with the
// fast raycaster at the given (high-quality) sampling into numbered PNG/TIFF files, each with its
// JSON sidecar, plus optionally a movie through OpenCV's VideoWriter (MP4 H.264, else MP4
// 'mp4v', else AVI 'MJPG'). Window-free: the app runs it in a BackgroundJob, the tests call it directly.
#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/volume.h"
#include "render/recipe_json.h"
#include "vessel/centerline.h"

namespace angio {

struct SeriesSpec {
  double startDeg = 0;
  double arcDeg = 360;          // a full turn leaves out the end (it is the start again)
  int count = 36;               // views, >= 1
  std::string format = "png";   // "png" (8-bit) or "tif" (16-bit)
  std::string prefix = "view";  // files prefix-000.png, prefix-001.png, ...
  bool movie = false;
  double movieFps = 12;
};

// The views' angles in degrees, wrapped into [0, 360): start + n * step, step = arc / count for a
// full turn (|arc| = 360), else arc / (count - 1) so that both ends are included.
std::vector<double> seriesAngles(double startDeg, double arcDeg, int count);

struct SeriesCallbacks {
  std::function<void(int done, int total)> progress;  // after each view
  const std::atomic<bool>* cancel = nullptr;          // set: stops within one image row
};

struct SeriesResult {
  std::vector<std::filesystem::path> images;  // written, in order (sidecars beside them)
  std::filesystem::path movie;                // empty if none was written
  std::string movieNote;                      // codec used, or why there is no movie
  bool cancelled = false;
  std::string summary;  // one line for the status bar
};

// Writes into `folder` (created if missing). `base` gives everything but the angle (its sampling
// is the one rendered): plain DVR/MIP, VesselGlyph or the DVR+CPR hybrid (render/render_recipe.h),
// each view rendered as `angioray render --params` of its sidecar renders it; `centerlines`
// (volume frame) are used iff base.vesselGlyph is set. Throws InputError/runtime_error (one
// line) on bad input or write errors.
SeriesResult exportRotationSeries(const Volume& volume, const Centerlines& centerlines,
                                  const RenderRecipe& base, const SeriesSpec& spec,
                                  const std::filesystem::path& folder, const SeriesCallbacks& callbacks);

}  // namespace angio
