#pragma once
// "Export image": the current view rendered at the high level's sampling with a chosen image
// sampling distance (e.g. 0.25 for print) into PNG/TIFF/EXR, with the render parameters in the
// file's metadata and a JSON sidecar (IMAGE.json, io/render_sidecar.h) to reproduce it with.
// Runs off the UI thread; cancellable.
#include <atomic>
#include <filesystem>
#include <string>

#include "core/image.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "gui/app_state.h"
#include "io/render_metadata.h"

namespace angio {


// What an export of the current view renders: the state's view at the high level's sampling with
// image sampling distance `isd`.
RenderDescription exportDescription(const AppState& state, const std::string& dataset, double isd);

// Writes `image` (rendered with `description` and `tf`) and its sidecar, each atomically.
void writeImageAndSidecar(const Image& image, const std::filesystem::path& path,
                          const TransferFunction& tf, const RenderDescription& description);

// Renders and writes the image and its sidecar. Returns a one-line summary; an empty string when
// `cancel` stopped it (nothing written). Throws InputError/runtime_error (one line) on failure,
// e.g. an image larger than kMaxImagePixels.
std::string exportView(const Volume& volume, const TransferFunction& tf,
                       const RenderDescription& description, const std::filesystem::path& path,
                       const std::atomic<bool>* cancel);

}  // namespace angio
