#pragma once
// Render one image with the reference raycaster and export it, with progress on stderr.
#include <filesystem>

#include "core/transfer_function.h"
#include "core/view_geometry.h"
#include "core/volume.h"
#include "io/render_metadata.h"

namespace angio {

// Throws if the image would be unreasonably large (more than kMaxImagePixels).
constexpr long kMaxImagePixels = 64L * 1024 * 1024;

// Throws (naming `out`) if the view's image has more than kMaxImagePixels.
void checkImageSize(const ViewGeometry& view, const std::filesystem::path& out);

enum class Raycaster { fast, reference };

// Renders with the chosen raycaster (the fast one gives the reference's image; the reference is
// kept to check it) and exports. Returns the render time in seconds, export excluded.
double renderAndExport(const Volume& volume, const TransferFunction& tf,
                       const RenderDescription& description, const std::filesystem::path& out,
                       Raycaster raycaster = Raycaster::fast);

// Parses "IxJxK" (e.g. "512x512x1200") into voxel counts; throws on anything else.
glm::ivec3 parseSize(const std::string& text);

}  // namespace angio
