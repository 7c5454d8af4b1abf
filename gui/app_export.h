#pragma once
// "Export image": the current view rendered at the high level's sampling with a chosen image
// sampling distance (e.g. 0.25 for print) into PNG/TIFF/EXR, with the render parameters in the
// file's metadata and a JSON sidecar (IMAGE.json, io/render_sidecar.h) to reproduce it with:
// plain DVR/MIP, VesselGlyph or the DVR+CPR hybrid, as the window shows it (the recipe is the
// sidecar, rendered by gui/sidecar_render.h as `angioray render --params` renders it).
// Runs off the UI thread; cancellable.
#include <atomic>
#include <filesystem>
#include <string>

#include "core/image.h"
#include "core/volume.h"
#include "gui/app_state.h"
#include "io/render_sidecar.h"
#include "vessel/centerline.h"

namespace angio {

// What an export of the current view renders: the state's view and TF at the high level's
// sampling with image sampling distance `isd`; plain DVR/MIP (the app adds its VesselGlyph and
// hybrid recipes when it shows them).
RenderSidecar exportSidecar(const AppState& state, const std::string& dataset, double isd);

// Writes `image` (rendered from `sidecar`) and its sidecar (with image = path), each atomically.
void writeImageAndSidecar(const Image& image, const std::filesystem::path& path, RenderSidecar sidecar);

// Renders and writes the image and its sidecar. `centerlines` (volume frame) are used iff
// sidecar.vesselGlyph is set. Returns a one-line summary; an empty string when `cancel` stopped
// it (nothing written). Throws InputError/runtime_error (one line) on failure, e.g. an image
// larger than kMaxImagePixels.
std::string exportView(const Volume& volume, const Centerlines& centerlines, const RenderSidecar& sidecar,
                       const std::filesystem::path& path, const std::atomic<bool>* cancel);

}  // namespace angio
