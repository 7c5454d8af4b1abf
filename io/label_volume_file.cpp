#include "io/label_volume_file.h"

#include <cstdint>

#include "io/grid_image_writing.h"

namespace angio {

void writeLabelVolume(const std::filesystem::path& file, const Volume& volume) {
  writeOnGrid<std::uint8_t>(volume, file, [](Voxel voxel) { return std::uint8_t(labelOf(voxel)); });
}

}  // namespace angio
