#pragma once
// Writes a label volume: the label bits (0..15) of a volume's voxels as a uint8 image on the same
// grid (dims, spacing, origin, direction), as MetaImage (.mha), NRRD (.nrrd) or NIfTI (.nii,
// .nii.gz), chosen by extension; the reader's --labels reads it back (io/volume_reader.h). Detached
// headers (.mhd, .nhdr) are refused: a label file is one file. Atomic (temp name, then rename).
// Throws InputError on failure.
#include <filesystem>

#include "core/volume.h"

namespace angio {

void writeLabelVolume(const std::filesystem::path& path, const Volume& labelsInVolumeBits);

}  // namespace angio
