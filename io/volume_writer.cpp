#include "io/volume_writer.h"

#include "io/grid_image_writing.h"

namespace angio {

void writeVolume(const Volume& volume, const std::filesystem::path& path) {
  writeOnGrid<short>(volume, path, [](Voxel voxel) { return short(densityOf(voxel) - kHuOffset); });
}

}  // namespace angio
