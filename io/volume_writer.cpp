#include "io/volume_writer.h"

#include "io/atomic_write.h"
#include "io/grid_image_writing.h"
#include "io/input_error.h"
#include "io/volume_formats.h"

namespace angio {

void writeVolume(const Volume& volume, const std::filesystem::path& path) {
  writeOnGrid<short>(volume, path, [](Voxel voxel) { return short(densityOf(voxel) - kHuOffset); });
}

void requireVolumeTarget(const std::filesystem::path& path) {
  if (!volumeFormatOf(path))
    throw InputError(path, "unknown volume format '" + path.extension().string() +
                               "' (use .mha, .mhd, .nrrd, .nhdr, .nii or .nii.gz)");
  requireWritableTarget(path);
}

}  // namespace angio
