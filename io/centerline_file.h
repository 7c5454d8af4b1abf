#pragma once
// Centerline files, chosen by extension: vmtk/VTK XML PolyData (.vtp), 3D Slicer markups curves
// (.mrk.json, .json) and CSV (.csv). Each loader returns the model of vessel/centerline.h in the
// physical (LPS, mm) frame, validated: an error (bad file, NaN, negative radius, empty path, no
// paths) throws InputError naming the file and, where there is one, the path; warnings (single-point
// paths, unknown radii) go to `warn`. Points outside a volume are checked once the volume is known:
// checkCenterlinesInside. Each writer keeps the path names and writes numbers that read back as the
// same doubles, so saving and loading gives the same model.
#include <filesystem>
#include <functional>
#include <string>

#include "core/volume.h"
#include "vessel/centerline.h"

namespace angio {

struct CenterlineLoadOptions {
  // Called with each warning as one line "<file>: <problem>"; may be empty.
  std::function<void(const std::string&)> warn;
};

// By extension (case-insensitive): .vtp, .mrk.json / .json, .csv; anything else is an InputError.
Centerlines loadCenterlines(const std::filesystem::path& file,
                            const CenterlineLoadOptions& options = {});

// By extension (case-insensitive): .mrk.json / .json, .vtp, .csv; anything else is an InputError
// naming the file. Writes atomically (io/atomic_write.h): on any error the file is as it was.
// Throws InputError naming the file if it cannot be written, std::logic_error if `centerlines` is
// not in the physical frame (files hold physical coordinates).
void saveCenterlines(const Centerlines& centerlines, const std::filesystem::path& file);
// Throws InputError unless saveCenterlines could write `file` (its format, its folder): for
// checking before a long computation.
void requireCenterlineTarget(const std::filesystem::path& file);

// Validates freshly parsed centerlines (validateCenterlines): throws InputError(file, problem) for
// the first error, passes each warning to options.warn. Used by every format's reader.
void checkLoadedCenterlines(const Centerlines& centerlines, const std::filesystem::path& file,
                            const CenterlineLoadOptions& options);

// Passes a warning to options.warn for each path with points outside the volume.
void checkCenterlinesInside(const Centerlines& centerlines, const Volume& volume,
                            const CenterlineLoadOptions& options);

// The whole file as bytes; throws InputError if it is missing or unreadable.
std::string readCenterlineFileBytes(const std::filesystem::path& file);

// For every format's writer: throws std::logic_error unless `centerlines` is in the physical frame;
// `format` names the format in the message.
void requirePhysicalFrame(const Centerlines& centerlines, const std::string& format);

}  // namespace angio
