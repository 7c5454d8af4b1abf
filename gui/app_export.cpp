#include "gui/app_export.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/fast_raycaster.h"
#include "core/slice_tiles.h"
#include "core/view_geometry.h"
#include "gui/render_job.h"
#include "io/atomic_write.h"
#include "io/image_export.h"
#include "io/tf_file.h"

namespace angio {

namespace {

nlohmann::json sidecarJson(const TransferFunction& tf, const RenderDescription& description,
                           const std::filesystem::path& image, int width, int height) {
  const RenderParams& p = description.params;
  return {
      {"image", image.filename().string()},
      {"width", width},
      {"height", height},
      {"dataset", description.dataset},
      {"axis", toString(p.axis)},
      {"angle_deg", p.angleDeg},
      {"mode", p.compositing == Compositing::mip ? "mip" : "dvr"},
      {"sampling", {{"isd", p.sampling.isd}, {"osd", p.sampling.osd},
                    {"filter", toString(p.sampling.filter)}, {"ert", p.sampling.ert}}},
      {"shading", {{"enabled", p.shading.enabled}, {"ka", p.shading.ka}, {"kd", p.shading.kd}}},
      {"mip", {{"window", p.mip.window}, {"level", p.mip.level}}},
      {"transfer_function", nlohmann::json::parse(toJson(tf))},
      {"metadata", renderMetadata(description)},
  };
}

}  // namespace

std::filesystem::path sidecarPath(const std::filesystem::path& image) {
  return std::filesystem::path(image.string() + ".json");
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
                                 FastRenderOptions{true, cancel}, &stats);
  if (stats.cancelled) return {};
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  exportImage(image, path, renderMetadata(description));
  const std::filesystem::path sidecar = sidecarPath(path);
  writeAtomically(sidecar, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp);
    out << sidecarJson(tf, description, path, image.width, image.height).dump(2) << '\n';
    if (!out) throw std::runtime_error(sidecar.string() + ": cannot be written");
  });
  char summary[512];
  std::snprintf(summary, sizeof summary, "exported %s (%dx%d, %.1f s) and %s", path.string().c_str(),
                image.width, image.height, seconds, sidecar.filename().string().c_str());
  return summary;
}

}  // namespace angio
