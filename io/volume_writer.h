#pragma once
// Writes a volume as MetaImage (.mha/.mhd), NRRD (.nrrd/.nhdr) or NIfTI (.nii/.nii.gz), chosen by
// extension: int16 HU (density - 1024), with spacing, origin and direction. Labels are not written.
// Atomic (temp name, then rename). Throws InputError on failure.
#include <filesystem>

#include "core/volume.h"

namespace angio {

void writeVolume(const Volume& volume, const std::filesystem::path& path);
// Throws InputError unless a volume could be written at `path` (a known format, a writable
// folder): for checking before a long computation.
void requireVolumeTarget(const std::filesystem::path& path);

}  // namespace angio
