#include "gui/render_job.h"

#include <chrono>
#include <cstdio>
#include <regex>
#include <stdexcept>
#include <string>

#include "core/fast_raycaster.h"
#include "core/reference_raycaster.h"
#include "core/view_geometry.h"
#include "gui/progress_line.h"
#include "io/image_export.h"

namespace angio {

namespace {

Image render(const Volume& volume, const TfTable& table, const RenderParams& params,
             Raycaster raycaster, ProgressLine& progress) {
  if (raycaster == Raycaster::reference) return renderReference(volume, table, params, std::ref(progress));
  const SliceTiles tiles = buildSliceTiles(volume, params.axis);
  return renderFast(volume, tiles, classifyTiles(tiles, table), table, params);
}

}  // namespace

void checkImageSize(const ViewGeometry& view, const std::filesystem::path& out) {
  if (long(view.width) * view.height > kMaxImagePixels)
    throw std::runtime_error(out.string() + ": image of " + std::to_string(view.width) + "x" +
                             std::to_string(view.height) +
                             " pixels is too large; use a larger --isd");
}

double renderAndExport(const Volume& volume, const TransferFunction& tf,
                       const RenderDescription& description, const std::filesystem::path& out,
                       Raycaster raycaster) {
  checkImageSize(makeViewGeometry(volume, description.params), out);
  const auto start = std::chrono::steady_clock::now();
  Image image;
  {
    ProgressLine progress("rendering " + out.filename().string());
    image = render(volume, buildTable(tf), description.params, raycaster, progress);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  exportImage(image, out, renderMetadata(description));
  std::printf("wrote %s (%dx%d, rendered in %.2f s)\n", out.string().c_str(), image.width,
              image.height, seconds);
  return seconds;
}

glm::ivec3 parseSize(const std::string& text) {
  static const std::regex pattern(R"((\d{1,5})x(\d{1,5})x(\d{1,5}))");
  std::smatch match;
  if (!std::regex_match(text, match, pattern))
    throw std::runtime_error("size '" + text + "' is not of the form IxJxK (e.g. 512x512x1200)");
  const glm::ivec3 size(std::stoi(match[1]), std::stoi(match[2]), std::stoi(match[3]));
  if (glm::any(glm::lessThan(size, glm::ivec3(8))) || glm::any(glm::greaterThan(size, glm::ivec3(4096))))
    throw std::runtime_error("size '" + text + "': each axis must be 8..4096 voxels");
  return size;
}

}  // namespace angio
