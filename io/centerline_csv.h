#pragma once
// Centerlines as CSV (RFC 4180): a header line `path,x_mm,y_mm,z_mm,radius_mm`, then one row per
// point, rows of a path in order, coordinates physical (mm, LPS) (the format of
// ../shared/data/aorta-centerlines.csv). `path` is the path's id: the writer uses the path's name,
// or its 0-based index if it has none; a field in double quotes may hold commas, quotes ("") and
// line breaks.
#include <filesystem>
#include <string>

#include "io/centerline_file.h"
#include "vessel/centerline.h"

namespace angio {

// Writes atomically (io/atomic_write.h); throws InputError naming the file if it cannot be written,
// or if two paths would get the same id (rows are grouped by id, so they would merge). Numbers are
// the shortest text that reads back as the same double. Names are quoted where they hold a comma,
// a quote or a line break, or begin or end with a space (the reader trims unquoted fields).
// `centerlines` must be in the physical frame (std::logic_error otherwise).
void writeCenterlinesCsv(const Centerlines& centerlines, const std::filesystem::path& file);

// Paths in order of their id's first row, named by the id. Spaces around unquoted fields and blank
// lines are ignored. Throws InputError (file, line, problem) for a missing or wrong header, a row
// without 5 fields, text that is not a number, a quoted field not closed, and the model's errors
// (NaN, negative radius, no rows); warnings go to options.warn.
Centerlines readCenterlinesCsv(const std::filesystem::path& file,
                               const CenterlineLoadOptions& options = {});
Centerlines parseCenterlinesCsv(const std::string& text, const std::filesystem::path& source,
                                const CenterlineLoadOptions& options = {});

}  // namespace angio
