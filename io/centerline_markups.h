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

// Throws InputError naming the file and the problem: bad JSON, no "markups" array, a position that
// is not 3 numbers, an unknown coordinate system or unit, a radius measurement whose length does
// not match the control points, and the model's errors (negative radius, empty path, no paths).
Centerlines readCenterlinesMarkups(const std::filesystem::path& file,
                                   const CenterlineLoadOptions& options = {});
Centerlines parseCenterlinesMarkups(const std::string& text, const std::filesystem::path& source,
                                    const CenterlineLoadOptions& options = {});

}  // namespace angio
