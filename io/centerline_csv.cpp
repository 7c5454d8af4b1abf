#include "io/centerline_csv.h"

#include <cstdio>
#include <fstream>

#include "io/atomic_write.h"
#include "io/input_error.h"

namespace angio {

namespace {

void writeRows(const std::vector<PhantomPath>& paths, std::ostream& out) {
  out << "path,x_mm,y_mm,z_mm,radius_mm\n";
  char row[160];
  for (std::size_t p = 0; p < paths.size(); ++p) {
    for (const PhantomCenterlinePoint& point : paths[p].points) {
      // Three decimals (micrometres), as in the reference file; snprintf is locale-independent
      // for the "C" locale the program runs in.
      std::snprintf(row, sizeof row, "%zu,%.3f,%.3f,%.3f,%.3f\n", p, point.positionMm.x,
                    point.positionMm.y, point.positionMm.z, point.radiusMm);
      out << row;
    }
  }
}

}  // namespace

void writeCenterlinesCsv(const std::vector<PhantomPath>& paths, const std::filesystem::path& file) {
  writeAtomically(file, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp, std::ios::binary);
    if (!out) throw InputError(file, "cannot open for writing");
    writeRows(paths, out);
    out.flush();
    if (!out) throw InputError(file, "write failed");
  });
}

}  // namespace angio
