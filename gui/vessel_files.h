#pragma once
// The Vessels section's paths written to a centerline file (io/centerline_file.h) and read back:
// what the file gives is what the app uses afterwards, so an export or a session that names the
// file renders what the window rendered, whatever precision the format keeps.
#include <filesystem>
#include <vector>

#include "gui/document.h"
#include "vessel/centerline.h"

namespace angio {

// Writes `physical` to `file` (by extension) and reads it back. Throws InputError naming the file.
Centerlines writeAndReadBack(const Centerlines& physical, const std::filesystem::path& file);

// The list with each traced path's centerline replaced by the one read back (in order, names kept).
std::vector<VesselPath> withReadBack(std::vector<VesselPath> paths, const Centerlines& readBack);

}  // namespace angio
