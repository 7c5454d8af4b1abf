#include "render/export.h"

#include <chrono>
#include <cstdio>

#include "io/image_export.h"
#include "io/input_error.h"
#include "render/frame_renderer.h"
#include "render/recipe_json.h"

namespace angio {

void checkImageSize(const ViewGeometry& view, const std::filesystem::path& out) {
  if (long(view.width) * view.height > kMaxImagePixels)
    throw InputError(out, "image of " + std::to_string(view.width) + "x" + std::to_string(view.height) +
                              " pixels is too large; use a larger isd");
}

void addImageAndSidecar(AtomicFileGroup& files, const Image& image, const std::filesystem::path& path,
                        RenderRecipe sidecar) {
  std::error_code error;
  sidecar.image = std::filesystem::absolute(path, error).lexically_normal().string();
  files.add(path, [&](const std::filesystem::path& file) {
    exportImage(image, file, renderSidecarMetadata(sidecar));
  });
  files.add(sidecarPathFor(path),
            [&](const std::filesystem::path& file) { saveRenderSidecar(sidecar, file); });
}

void writeImageAndSidecar(const Image& image, const std::filesystem::path& path, RenderRecipe sidecar) {
  // Both or neither: an image whose sidecar could not be written would not reproduce.
  AtomicFileGroup files;
  addImageAndSidecar(files, image, path, std::move(sidecar));
  files.commit();
}

std::string exportView(const Volume& volume, const Centerlines& centerlines, const RenderRecipe& sidecar,
                       const std::filesystem::path& path, const std::atomic<bool>* cancel) {
  checkImageSize(makeViewGeometry(volume, sidecar.params), path);
  const auto start = std::chrono::steady_clock::now();
  FastRenderStats stats;
  const Image image = renderRecipe(volume, centerlines, sidecar, {.cancel = cancel}, {}, &stats);
  if (stats.cancelled) return {};
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeImageAndSidecar(image, path, sidecar);
  char summary[512];
  std::snprintf(summary, sizeof summary, "exported %s (%dx%d, %.1f s) and %s", path.string().c_str(),
                image.width, image.height, seconds, sidecarPathFor(path).filename().string().c_str());
  return summary;
}

}  // namespace angio
