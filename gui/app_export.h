#pragma once
// "Export image": the current view rendered at the high level's sampling with a chosen image
// sampling distance (e.g. 0.25 for print) into PNG/TIFF/EXR, with the render parameters in the
// file's metadata and a JSON sidecar (IMAGE.json) holding everything needed to reproduce it.
// Runs off the UI thread; cancellable.
#include <atomic>
#include <filesystem>
#include <string>

#include "core/transfer_function.h"
#include "core/volume.h"
#include "io/render_metadata.h"

namespace angio {

// The sidecar of an exported image: IMAGE + ".json" (e.g. view.png.json).
std::filesystem::path sidecarPath(const std::filesystem::path& image);

// Renders and writes the image and its sidecar. Returns a one-line summary; an empty string when
// `cancel` stopped it (nothing written). Throws InputError/runtime_error (one line) on failure,
// e.g. an image larger than kMaxImagePixels.
std::string exportView(const Volume& volume, const TransferFunction& tf,
                       const RenderDescription& description, const std::filesystem::path& path,
                       const std::atomic<bool>* cancel);

}  // namespace angio
