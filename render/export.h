#pragma once
// Exports of rendered views: the image (PNG/TIFF/EXR with the recipe in its metadata) and its JSON
// sidecar (render/recipe_json.h) beside it, written together or not at all, so that
// `angioray render --params` of the sidecar gives the image again. The window's "Export image",
// rotation series and `angioray render` all write through here.
#include <atomic>
#include <filesystem>
#include <string>

#include "core/image.h"
#include "core/view_geometry.h"
#include "core/volume.h"
#include "io/atomic_write.h"
#include "render/recipe_json.h"
#include "vessel/centerline.h"

namespace angio {

// The largest image angioray renders (pixels): 64 Mpixel of float RGBA is 1 GiB.
constexpr long kMaxImagePixels = 64L * 1024 * 1024;

// Throws InputError naming `out` if the view's image has more than kMaxImagePixels.
void checkImageSize(const ViewGeometry& view, const std::filesystem::path& out);

// Writes `image` (rendered from `sidecar`) and its sidecar (with image = path): both or neither.
void writeImageAndSidecar(const Image& image, const std::filesystem::path& path, RenderRecipe sidecar);
// The same, as part of a larger group (a rotation series) that the caller commits.
void addImageAndSidecar(AtomicFileGroup& files, const Image& image, const std::filesystem::path& path,
                        RenderRecipe sidecar);

// Renders and writes the image and its sidecar. `centerlines` (volume frame) are used iff
// sidecar.vesselGlyph is set. Returns a one-line summary; an empty string when `cancel` stopped
// it (nothing written). Throws InputError (one line) on failure, e.g. an image larger than
// kMaxImagePixels.
std::string exportView(const Volume& volume, const Centerlines& centerlines, const RenderRecipe& sidecar,
                       const std::filesystem::path& path, const std::atomic<bool>* cancel);

}  // namespace angio
