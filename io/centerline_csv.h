#pragma once
// Ground-truth centerlines as CSV: a header line, then `path,x_mm,y_mm,z_mm,radius_mm` rows, path
// being the 0-based index of the path, rows of a path in order (the format of
// ../shared/data/aorta-centerlines.csv).
#include <filesystem>
#include <vector>

#include "core/phantom.h"

namespace angio {

// Writes atomically (io/atomic_write.h); throws InputError naming the file if it cannot be written.
void writeCenterlinesCsv(const std::vector<PhantomPath>& paths, const std::filesystem::path& file);

}  // namespace angio
