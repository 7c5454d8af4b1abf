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
  const RayRegions* regions;
  ViewGeometry view;
  FrameTables tables;
  RayTemplates templates;
};

// Per row: which tiles may hold a visible sample (DVR) or the largest density a sample can
// take there (MIP), over the slices the row's samples read.
struct RowTiles {
  std::vector<std::uint8_t> visible;         // per tile (DVR)
  std::vector<std::uint16_t> maxDensity;     // per tile (MIP)
  std::vector<std::uint8_t> groupVisible;    // per tile group: any tile in it visible
  std::vector<std::uint16_t> groupMaxDensity;
};

void classifyRow(const Frame& f, double qa, RowTiles& row) {
  const SliceSpan span = slicesReadAt(f.tiles, qa, f.params.sampling.filter);
  const std::size_t perSlice = f.tiles.tilesPerSlice();
  const bool mip = f.params.compositing == Compositing::mip;
  row.maxDensity.assign(perSlice, 0);
  row.visible.assign(perSlice, 0);
  const bool wide = f.params.sampling.filter == Filter::mean;
  const auto& sliceMax = wide ? f.tiles.wideMaxDensity : f.tiles.maxDensity;
  const std::uint8_t bit = visibilityBit(f.params.sampling.filter);
  for (int s = span.first; s <= span.last; ++s) {
    const std::size_t base = perSlice * s;
    for (std::size_t t = 0; t < perSlice; ++t) {
      if (mip) row.maxDensity[t] = std::max(row.maxDensity[t], sliceMax[base + t]);
      else row.visible[t] |= f.visibleTiles[base + t] & bit;
    }
  }
  const std::size_t groups = std::size_t(f.tiles.groupsB()) * f.tiles.groupsC();
  row.groupVisible.assign(groups, 0);
  row.groupMaxDensity.assign(groups, 0);
  for (int t = 0; t < int(perSlice); ++t) {
    const int g = f.tiles.groupOf(t);
    if (mip) row.groupMaxDensity[g] = std::max(row.groupMaxDensity[g], row.maxDensity[t]);
    else row.groupVisible[g] |= row.visible[t];
  }
}

// A tile (or group) may be skipped when no sample in it can change the pixel: nothing visible
// there (DVR), or nothing denser than the maximum so far (MIP).
bool maySkip(const Frame& f, std::uint8_t visible, std::uint16_t maxDensity, float mipMaximum) {
  if (!f.options.skipEmpty) return false;
  if (f.params.compositing == Compositing::mip) return float(maxDensity) <= mipMaximum;
  return !visible;
}

// The samples of one tile run, composited into the ray (DVR) or into its maximum (MIP).
// Returns true when the ray terminated early.
bool sampleRun(const Frame& f, const RaySamples& positions, const TileRun& run, RegionCursor& regions,
               RayAccumulator& ray, float& mipMaximum) {
  const Filter filter = f.params.sampling.filter;
  const bool mip = f.params.compositing == Compositing::mip;
  for (long k = run.firstSample; k < run.firstSample + run.count; ++k) {
    const SampleTable* table = f.tables.of(regions.at(double(k) * f.view.sampleMm));
    if (!table) continue;  // a clipped region
    const glm::dvec3 q = positions.at(k);
    const float density = sampleDensity(f.volume, q, filter);
    if (mip) {
      mipMaximum = std::max(mipMaximum, density);
      continue;
    }
    const glm::vec4 rgba = (*table)[tableIndex(density)];
    if (rgba.a <= 0.f) continue;
    ray.add(rgba, shadingFactor(f.params.shading, sampleGradient(f.volume, q, filter),
                                glm::vec3(f.view.viewDir)));
    if (ray.opacity >= f.params.sampling.ert) return true;
  }
  return false;
}

glm::vec4 castRay(const Frame& f, const RowTiles& row, const glm::dvec3& origin, int x, int y,
                  std::uint64_t& samples) {
  const std::uint32_t firstGroup = f.templates.columnBegin[x], endGroup = f.templates.columnBegin[x + 1];
  if (firstGroup == endGroup) return glm::vec4(0.f);  // the ray misses the volume
  const RaySamples positions(f.volume, f.view, origin);
  RegionCursor regions(f.regions, x, y);
  RayAccumulator ray;
  float mipMaximum = 0.f;
  for (std::uint32_t g = firstGroup; g < endGroup; ++g) {
    const GroupRun& group = f.templates.groups[g];
    if (maySkip(f, row.groupVisible[group.group], row.groupMaxDensity[group.group], mipMaximum)) continue;
    for (std::uint32_t r = group.firstRun; r < group.endRun; ++r) {
      const TileRun& run = f.templates.runs[r];
      if (maySkip(f, row.visible[run.tile], row.maxDensity[run.tile], mipMaximum)) continue;
      samples += run.count;
      if (sampleRun(f, positions, run, regions, ray, mipMaximum)) return ray.pixel();
    }
  }
  return f.params.compositing == Compositing::mip ? mipPixel(mipMaximum, f.params.mip) : ray.pixel();
}

bool cancelRequested(const FastRenderOptions& options) {
  return options.cancel && options.cancel->load(std::memory_order_relaxed);
}

// Renders one row; returns false if cancelled part-way. The flag is read every 64 pixels, so a
// high-quality row of a large volume (~20 ms) still stops within a few milliseconds.
bool renderRow(const Frame& f, int y, RowTiles& row, Image& image, std::uint64_t& samples) {
  const double axisMm = f.view.rayOrigin(0, y)[f.view.axis];
  // Rows above or below the domain see nothing (the reference's slab test, see sampleRange).
  if (axisMm < -1e-9 || axisMm > f.view.extent[f.view.axis] + 1e-9) return true;
  classifyRow(f, axisMm / f.volume.spacing[f.view.axis], row);
  for (int x = 0; x < f.view.width; ++x) {
    if (x % 64 == 0 && cancelRequested(f.options)) return false;
    image.at(x, y) = castRay(f, row, f.view.rayOrigin(x, y), x, y, samples);
  }
  return true;
}

}  // namespace

Image renderFast(const Volume& volume, const SliceTiles& tiles,
                 const std::vector<std::uint8_t>& visibleTiles, const TfTable& table,
                 const RenderParams& params, const FastRenderOptions& options,
                 FastRenderStats* stats) {
  return renderFast(volume, tiles, visibleTiles, singleTable(table), params, options, stats);
}

std::vector<std::uint8_t> classifyTiles(const SliceTiles& tiles, const RegionTables& tables) {
  std::vector<std::uint8_t> visible(tiles.minDensity.size(), 0);
  for (const TfTable* table : {tables.regions ? tables.focus : nullptr,
                               tables.regions ? tables.context : nullptr, tables.outside}) {
    if (!table) continue;
    const std::vector<std::uint8_t> byTable = classifyTiles(tiles, *table);
    for (std::size_t n = 0; n < visible.size(); ++n) visible[n] |= byTable[n];
  }
  return visible;
}

Image renderFast(const Volume& volume, const SliceTiles& tiles,
                 const std::vector<std::uint8_t>& visibleTiles, const RegionTables& tables,
                 const RenderParams& params, const FastRenderOptions& options,
                 FastRenderStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  Frame f{volume, tiles, visibleTiles, params, options, tables.regions, makeViewGeometry(volume, params),
          frameTables(tables, params.sampling.osd), {}};
  f.templates = buildRayTemplates(volume, f.view, tiles);
  const double templateMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  Image image = makeImage(f.view.width, f.view.height);
  std::atomic<std::uint64_t> samples{0};
  std::atomic<bool> cancelled{false};
  tbb::parallel_for(tbb::blocked_range<int>(0, f.view.height), [&](const tbb::blocked_range<int>& rows) {
    RowTiles row;
    std::uint64_t local = 0;
    for (int y = rows.begin(); y != rows.end(); ++y)
      if (!renderRow(f, y, row, image, local)) {
        cancelled = true;
        break;
      }
    samples += local;
  });
  if (stats) *stats = {samples.load(), templateMs, cancelled.load()};
  return image;
}

}  // namespace angio
