#pragma once
// Checking that a volume file holds all the voxel data its header promises, before reading it.
// ITK's MetaImage and NIfTI readers accept short files (NIfTI zero-fills the rest, MetaImage only
// prints to stderr), so without this a truncated copy would load with part of the volume missing.
#include <cstdint>
#include <filesystem>

#include "io/volume_formats.h"

namespace angio {

// Throws InputError naming `file` if it is truncated. `voxelBytes` is the size of the voxel data
// as ITK reports it for the header (used for MetaImage, whose element sizes ITK knows best).
// Layouts it cannot check (MetaImage file lists, NRRD, whose reader checks itself) pass.
void requireCompleteData(const std::filesystem::path& file, VolumeFormat format,
                         std::uint64_t voxelBytes);

}  // namespace angio
