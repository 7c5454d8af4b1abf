#pragma once
// Writes a volume's segmentation labels (the 4 label bits of every voxel, rendering-model.md
// "Labels") as a uint8 label map on the volume's grid, with the spacing, origin and direction the
// density volume writer uses: `ReadOptions::labelPath` reads it back onto the same volume, and
// other programs (3D Slicer, ITK-SNAP) place it over the CT written by writeVolume. Format by
// extension: .nrrd, .nhdr, .nii, .nii.gz, .mha, .mhd. Atomic (temp name, then rename). Throws
// InputError naming the file.
#include <filesystem>

#include "core/volume.h"

namespace angio {

void writeLabelVolume(const std::filesystem::path& file, const Volume& volume);

}  // namespace angio
