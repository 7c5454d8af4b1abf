#include "gui/vessel_files.h"

#include "io/centerline_file.h"

namespace angio {

Centerlines writeAndReadBack(const Centerlines& physical, const std::filesystem::path& file) {
  saveCenterlines(physical, file);
  return loadCenterlines(file);
}

std::vector<VesselPath> withReadBack(std::vector<VesselPath> paths, const Centerlines& readBack) {
  std::size_t next = 0;
  for (VesselPath& path : paths) {
    if (path.centerline.points.size() < 2 || next >= readBack.paths.size()) continue;
    path.centerline.points = readBack.paths[next++].points;
  }
  return paths;
}

}  // namespace angio
