#pragma once
// Centerlines as CSV: a header line `path,x_mm,y_mm,z_mm,radius_mm`, then one row per point, path
// being the path's id (the writer uses the 0-based index), rows of a path in order, coordinates
// physical (mm, LPS) (the format of ../shared/data/aorta-centerlines.csv).
#include <filesystem>
#include <string>

#include "io/centerline_file.h"
#include "vessel/centerline.h"

namespace angio {

// Writes atomically (io/atomic_write.h); throws InputError naming the file if it cannot be written.
// Coordinates and radii with three decimals (micrometres). Path names are not kept: a path's id is
// its index. `centerlines` must be in the physical frame (std::logic_error otherwise).
void writeCenterlinesCsv(const Centerlines& centerlines, const std::filesystem::path& file);

// Paths in order of their id's first row, named by the id. Throws InputError (file, line, problem)
// for a missing or wrong header, a row without 5 fields, text that is not a number, and the
// model's errors (NaN, negative radius, no rows); warnings go to options.warn.
Centerlines readCenterlinesCsv(const std::filesystem::path& file,
                               const CenterlineLoadOptions& options = {});
Centerlines parseCenterlinesCsv(const std::string& text, const std::filesystem::path& source,
                                const CenterlineLoadOptions& options = {});

}  // namespace angio
