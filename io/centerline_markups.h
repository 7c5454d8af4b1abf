#pragma once
// 3D Slicer markups curves (.mrk.json; Slicer's markups JSON schema v1.0.x):
//   {"markups": [{"type": "Curve", "name": "...", "coordinateSystem": "LPS" | "RAS",
//     "coordinateUnits": "mm" | "um", "controlPoints": [{"position": [x, y, z], ...}, ...],
//     "measurements": [{"name": "Radius", "controlPointValues": [r, ...]}, ...]}, ...]}
// Each "Curve" or "Line" markup is one path, named by its "name" (else its index in the file);
// other markup types are skipped with a warning. RAS coordinates become LPS as (-x, -y, z).
// The radius comes from a measurement named "Radius" (any case) with one value per control point
// (as SlicerVMTK's centerline curves have); without one the radii are 0 (unknown, with a warning).
// Control points whose positionStatus is "undefined" have no position and are skipped.
#include <filesystem>
#include <string>

#include "io/centerline_file.h"
#include "vessel/centerline.h"

namespace angio {

// Writes atomically one "Curve" markup per path, as Slicer and SlicerVMTK write centerline curves:
// "name" the path's name, LPS millimetres, control points with id, label ("<name>-<n>"), position,
// Slicer's identity orientation, selected/locked/visibility and positionStatus "defined", and the
// radii as the measurement "Radius" (controlPointValues). Numbers are the shortest text that reads
// back as the same double. Throws InputError naming the file if it cannot be written;
// `centerlines` must be in the physical frame (std::logic_error otherwise).
void writeCenterlinesMarkups(const Centerlines& centerlines, const std::filesystem::path& file);

// Throws InputError naming the file and the problem: bad JSON, no "markups" array, a position that
// is not 3 numbers, an unknown coordinate system or unit, a radius measurement whose length does
// not match the control points, and the model's errors (negative radius, empty path, no paths).
Centerlines readCenterlinesMarkups(const std::filesystem::path& file,
                                   const CenterlineLoadOptions& options = {});
Centerlines parseCenterlinesMarkups(const std::string& text, const std::filesystem::path& source,
                                    const CenterlineLoadOptions& options = {});

}  // namespace angio
