#include "gui/app_export.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "core/fast_raycaster.h"
#include "core/slice_tiles.h"
#include "core/view_geometry.h"
#include "gui/render_job.h"
#include "io/image_export.h"
#include "io/render_sidecar.h"

namespace angio {

RenderDescription exportDescription(const AppState& state, const std::string& dataset, double isd) {
  RenderDescription description;
  description.dataset = dataset;
  description.transferFunction = state.tf.name;
  description.quality = Quality::high;
  description.params = renderParamsOf(state);
  description.params.sampling = state.levels[int(Quality::high)];
  description.params.sampling.isd = isd;
  return description;
}

void writeImageAndSidecar(const Image& image, const std::filesystem::path& path,
                          const TransferFunction& tf, const RenderDescription& description) {
  RenderSidecar sidecar;
  std::error_code error;
  sidecar.image = std::filesystem::absolute(path, error).lexically_normal().string();
  sidecar.dataset = absoluteDataset(description.dataset);
  sidecar.quality = description.quality;
  sidecar.params = description.params;
  sidecar.tf = tf;
  exportImage(image, path, renderSidecarMetadata(sidecar));
  saveRenderSidecar(sidecar, sidecarPathFor(path));
}

std::string exportView(const Volume& volume, const TransferFunction& tf,
                       const RenderDescription& description, const std::filesystem::path& path,
                       const std::atomic<bool>* cancel) {
  const ViewGeometry view = makeViewGeometry(volume, description.params);
  if (long(view.width) * view.height > kMaxImagePixels)
    throw std::runtime_error(path.string() + ": image of " + std::to_string(view.width) + "x" +
                             std::to_string(view.height) + " pixels is too large; use a larger isd");
  const auto start = std::chrono::steady_clock::now();
  const TfTable table = buildTable(tf);
  const SliceTiles tiles = buildSliceTiles(volume, description.params.axis);
  FastRenderStats stats;
  const Image image = renderFast(volume, tiles, classifyTiles(tiles, table), table, description.params,
                                 FastRenderOptions{.cancel = cancel}, &stats);
  if (stats.cancelled) return {};
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeImageAndSidecar(image, path, tf, description);
  const std::filesystem::path sidecar = sidecarPathFor(path);
  char summary[512];
  std::snprintf(summary, sizeof summary, "exported %s (%dx%d, %.1f s) and %s", path.string().c_str(),
                image.width, image.height, seconds, sidecar.filename().string().c_str());
  return summary;
}

}  // namespace angio
