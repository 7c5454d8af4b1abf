#include "gui/vessel_files.h"

#include "io/centerline_csv.h"
#include "io/centerline_file.h"
#include "io/input_error.h"

namespace angio {

Centerlines writeAndReadBack(const Centerlines& physical, const std::filesystem::path& file) {
  const std::string name = file.filename().string();
  if (name.size() < 4 || name.substr(name.size() - 4) != ".csv")
    throw InputError(file, "centerlines are written as .csv for now");
  writeCenterlinesCsv(physical, file);
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
