#pragma once
// The spacing, origin and axes a volume file's header declares, checked as written before ITK
// reads them: its readers replace a spacing they cannot use (NaN, 0) by 1 mm and accept NaN in an
// orientation, which would load the scan at the wrong size or nowhere.
#include <filesystem>

#include "io/volume_formats.h"

namespace angio {

// Throws InputError naming the file and the field when a declared spacing is not a positive
// finite number, or an origin or axis is not finite (or an axis has no length).
void checkDeclaredGeometry(const std::filesystem::path& file, VolumeFormat format);

}  // namespace angio
