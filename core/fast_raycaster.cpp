#include "core/fast_raycaster.h"

#include <chrono>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/compositing.h"
#include "core/ray_templates.h"
#include "core/volume_sampling.h"

namespace angio {

namespace {

struct Frame {
  const Volume& volume;
  const SliceTiles& tiles;
  const std::vector<std::uint8_t>& visibleTiles;
  const RenderParams& params;
  const FastRenderOptions& options;
  ViewGeometry view;
  SampleTable table;
  RayTemplates templates;
};

// Per row: which tiles may hold a visible sample (DVR) or the largest density a sample can
// take there (MIP), over the slices the row's samples read.
struct RowTiles {
  std::vector<std::uint8_t> visible;
  std::vector<std::uint16_t> maxDensity;
};

void classifyRow(const Frame& f, double qa, RowTiles& row) {
  const SliceSpan span = slicesReadAt(f.tiles, qa);
  const std::size_t perSlice = f.tiles.tilesPerSlice();
  const bool mip = f.params.compositing == Compositing::mip;
  if (mip) row.maxDensity.assign(perSlice, 0);
  else row.visible.assign(perSlice, 0);
  for (int s = span.first; s <= span.last; ++s) {
    const std::size_t base = perSlice * s;
    for (std::size_t t = 0; t < perSlice; ++t) {
      if (mip) row.maxDensity[t] = std::max(row.maxDensity[t], f.tiles.maxDensity[base + t]);
      else row.visible[t] |= f.visibleTiles[base + t];
    }
  }
}

bool runMaySkip(const Frame& f, const RowTiles& row, const TileRun& run, float mipMaximum) {
  if (!f.options.skipEmpty) return false;
  if (f.params.compositing == Compositing::mip) return float(row.maxDensity[run.tile]) <= mipMaximum;
  return !row.visible[run.tile];
}

glm::vec4 castRay(const Frame& f, const RowTiles& row, const glm::dvec3& origin, int x,
                  std::uint64_t& samples) {
  const Filter filter = f.params.sampling.filter;
  const glm::vec3 viewDir(f.view.viewDir);
  const bool mip = f.params.compositing == Compositing::mip;
  const std::uint32_t firstRun = f.templates.columnBegin[x], endRun = f.templates.columnBegin[x + 1];
  if (firstRun == endRun) return glm::vec4(0.f);  // the ray misses the volume
  RayAccumulator ray;
  float mipMaximum = 0.f;
  for (std::uint32_t r = firstRun; r < endRun; ++r) {
    const TileRun& run = f.templates.runs[r];
    if (runMaySkip(f, row, run, mipMaximum)) continue;
    samples += run.count;
    for (long k = run.firstSample; k < run.firstSample + run.count; ++k) {
      const glm::dvec3 q = sampleCoordinate(f.volume, f.view, origin, k);
      const float density = sampleDensity(f.volume, q, filter);
      if (mip) {
        mipMaximum = std::max(mipMaximum, density);
        continue;
      }
      const glm::vec4 rgba = f.table[tableIndex(density)];
      if (rgba.a <= 0.f) continue;
      ray.add(rgba, shadingFactor(f.params.shading, sampleGradient(f.volume, q, filter), viewDir));
      if (ray.opacity >= f.params.sampling.ert) return ray.pixel();
    }
  }
  return mip ? mipPixel(mipMaximum, f.params.mip) : ray.pixel();
}

void renderRow(const Frame& f, int y, RowTiles& row, Image& image, std::uint64_t& samples) {
  const double axisMm = f.view.rayOrigin(0, y)[f.view.axis];
  // Rows above or below the domain see nothing (the reference's slab test, see sampleRange).
  if (axisMm < -1e-9 || axisMm > f.view.extent[f.view.axis] + 1e-9) return;
  classifyRow(f, axisMm / f.volume.spacing[f.view.axis], row);
  for (int x = 0; x < f.view.width; ++x)
    image.at(x, y) = castRay(f, row, f.view.rayOrigin(x, y), x, samples);
}

}  // namespace

Image renderFast(const Volume& volume, const SliceTiles& tiles,
                 const std::vector<std::uint8_t>& visibleTiles, const TfTable& table,
                 const RenderParams& params, const FastRenderOptions& options,
                 FastRenderStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  Frame f{volume, tiles, visibleTiles, params, options, makeViewGeometry(volume, params),
          correctedTable(table, params.sampling.osd), {}};
  f.templates = buildRayTemplates(volume, f.view, tiles);
  const double templateMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  Image image = makeImage(f.view.width, f.view.height);
  std::atomic<std::uint64_t> samples{0};
  std::atomic<bool> cancelled{false};
  tbb::parallel_for(tbb::blocked_range<int>(0, f.view.height), [&](const tbb::blocked_range<int>& rows) {
    RowTiles row;
    std::uint64_t local = 0;
    for (int y = rows.begin(); y != rows.end(); ++y) {
      if (options.cancel && options.cancel->load(std::memory_order_relaxed)) {
        cancelled = true;
        break;
      }
      renderRow(f, y, row, image, local);
    }
    samples += local;
  });
  if (stats) *stats = {samples.load(), templateMs, cancelled.load()};
  return image;
}

}  // namespace angio
