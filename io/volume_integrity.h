#pragma once
// Checking that a volume file holds all the voxel data its header promises, before reading it.
// ITK's MetaImage and NIfTI readers accept short files (NIfTI zero-fills the rest, MetaImage only
// prints to stderr), so without this a truncated copy would load with part of the volume missing.
#include <cstdint>
#include <filesystem>

#include "io/volume_formats.h"
#include "io/voxel_data_layout.h"

namespace angio {

// Throws InputError naming `file` if it is truncated. `size` is the voxel data's size as ITK
// reports it for the header (used for MetaImage, whose element sizes ITK knows best). Layouts it
// cannot check (MetaImage file lists; NRRD: requireCompleteNrrdData) pass.
void requireCompleteData(const std::filesystem::path& file, VolumeFormat format,
                         const StoredDataSize& size);

// The same for NRRD data that io/ reads itself (raw or gzip, attached or in one data file): teem
// checks only after allocating the volume, and its gzip reader decompresses up to the end first.
void requireCompleteNrrdData(const std::filesystem::path& file, const VoxelDataLayout& layout,
                             std::uint64_t voxelBytes);

// The same for NRRD data as text or hex (other encodings pass), which teem allocates the volume
// for before parsing: text takes a digit and a separator per value (but the last), hex two digits
// per byte (line and byte skips only make the data shorter).
void requireCompleteNrrdText(const std::filesystem::path& file, const NrrdDataStart& start,
                             const StoredDataSize& size);

}  // namespace angio
