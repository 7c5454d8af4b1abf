#include "core/fast_raycaster.h"

#include <chrono>
#include <limits>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/compositing.h"
#include "core/ray_samplers.h"
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
  const RegionTables& regionTables;
  ViewGeometry view;
  FrameTables tables;
  RayTemplates templates;

  glm::dvec3 rayStepQ{0.0};  // from one sample to the next, voxel units (RaySamples::stepQ)
  bool skipGroups = true, skipTiles = true, skipCells = true;  // FastRenderOptions, resolved
  // Visible where any region's TF is: a cell hidden from it is hidden from every sample in it.
  const TfTable* anyRegionTf = nullptr;

  // The uncorrected TF of a region, for visibility queries (nullptr: clipped).
  const TfTable* tfOf(Region region) const {
    switch (region) {
      case Region::focus: return regionTables.regions ? regionTables.focus : nullptr;
      case Region::context: return regionTables.regions ? regionTables.context : nullptr;
      case Region::outside: return regionTables.outside;
    }
    return nullptr;
  }
};

// Per row: which tiles may hold a visible sample (DVR) or the largest density a sample can
// take there (MIP), over the slices the row's samples read. Rows reading the same slices share it.
struct RowTiles {
  SliceSpan span{0, -1};
  std::vector<std::uint8_t> visible;         // per tile (DVR)
  std::vector<std::uint16_t> maxDensity;     // per tile (MIP)
  std::vector<std::uint8_t> groupVisible;    // per tile group: any tile in it visible
  std::vector<std::uint16_t> groupMaxDensity;
};

void classifyRow(const Frame& f, double qa, RowTiles& row) {
  const SliceSpan span = slicesReadAt(f.tiles, qa, f.params.sampling.filter);
  if (span.first == row.span.first && span.last == row.span.last) return;
  row.span = span;
  const std::size_t perSlice = f.tiles.tilesPerSlice();
  const bool mip = f.params.compositing == Compositing::mip;
  row.maxDensity.assign(perSlice, 0);
  row.visible.assign(perSlice, 0);
  const bool wide = f.params.sampling.filter == Filter::mean;
  const auto& sliceMax = wide ? f.tiles.wideMaxDensity : f.tiles.maxDensity;
  const std::uint8_t bit = visibilityBit(f.params.sampling.filter);
  for (int s = span.first; s <= span.last; ++s) {
    const std::size_t base = perSlice * s;
    if (mip) {
      std::uint16_t* __restrict out = row.maxDensity.data();
      const std::uint16_t* __restrict in = sliceMax.data() + base;
      for (std::size_t t = 0; t < perSlice; ++t) out[t] = std::max(out[t], in[t]);
    } else {
      std::uint8_t* __restrict out = row.visible.data();
      const std::uint8_t* __restrict in = f.visibleTiles.data() + base;
      for (std::size_t t = 0; t < perSlice; ++t) out[t] |= in[t] & bit;
    }
  }
  const std::size_t groups = std::size_t(f.tiles.groupsB()) * f.tiles.groupsC();
  row.groupVisible.assign(groups, 0);
  row.groupMaxDensity.assign(groups, 0);
  // Tile rows in order, each tile into its group (kGroupTiles^2 tiles): no index table.
  const int tilesB = f.tiles.tilesB, groupsB = f.tiles.groupsB();
  for (int tc = 0; tc < f.tiles.tilesC; ++tc) {
    const std::size_t rowBase = std::size_t(tc) * tilesB;
    const std::size_t groupBase = std::size_t(tc / kGroupTiles) * groupsB;
    for (int tb = 0; tb < tilesB; ++tb) {
      const std::size_t g = groupBase + tb / kGroupTiles;
      if (mip) row.groupMaxDensity[g] = std::max(row.groupMaxDensity[g], row.maxDensity[rowBase + tb]);
      else row.groupVisible[g] |= row.visible[rowBase + tb];
    }
  }
}

// A tile (or group) may be skipped when no sample in it can change the pixel: nothing visible
// there (DVR), or nothing denser than the maximum so far (MIP).
bool maySkip(bool enabled, const Frame& f, std::uint8_t visible, std::uint16_t maxDensity,
             float mipMaximum) {
  if (!enabled) return false;
  if (f.params.compositing == Compositing::mip) return float(maxDensity) <= mipMaximum;
  return !visible;
}

// What a ray carries from one tile group to the next.
template <class Sampler>
struct RayState {
  RaySamples positions;
  RegionCursor regions;
  Sampler sampler;
  RayAccumulator ray;
  float mipMaximum = 0.f;
  long resumeAt = std::numeric_limits<long>::min();  // samples before it are in a clipped region
  bool terminated = false;
};

// The samples of one tile run, composited into the ray (DVR) or into its maximum (MIP).
// Returns true when the ray terminated early. Samples the sampler proves invisible (or, in MIP,
// not above the maximum) are skipped without interpolation; they could not change the pixel.
template <bool Mip, class Sampler>
bool sampleRun(const Frame& f, const TileRun& run, RayState<Sampler>& state) {
  const bool skip = f.skipCells;
  const glm::vec3 viewDir(f.view.viewDir);
  Sampler& sampler = state.sampler;
  for (long k = std::max(run.firstSample, state.resumeAt); k < run.firstSample + run.count; ++k) {
    const double t = double(k) * f.view.sampleMm;
    const Region region = state.regions.at(t);
    const SampleTable* table = f.tables.of(region);
    if (!table) {
      // A clipped region (VesselGlyph): leap to just before its end. The sample there is
      // classified as every other one, so the leap needs no exact division.
      const double change = state.regions.nextChange(t);
      if (change == std::numeric_limits<double>::infinity()) return true;  // nothing more shown
      state.resumeAt = std::max(k + 1, long(change / f.view.sampleMm) - 1);
      k = state.resumeAt - 1;
      continue;
    }
    sampler.moveTo(state.positions.at(k));
    if constexpr (Mip) {
      if (skip && sampler.maxDensity() <= state.mipMaximum) {
        k += sampler.samplesLeftInCell();
        continue;
      }
      state.mipMaximum = std::max(state.mipMaximum, sampler.density());
    } else {
      if (skip && !sampler.mayBeVisible(*f.tfOf(region))) {
        if (!sampler.mayBeVisible(*f.anyRegionTf)) k += sampler.samplesLeftInCell();
        continue;
      }
      const glm::vec4 rgba = (*table)[tableIndex(sampler.density())];
      if (rgba.a <= 0.f) continue;
      const float shade = f.params.shading.enabled
                              ? shadingFactor(f.params.shading, sampler.gradient(), viewDir)
                              : 1.f;
      state.ray.add(rgba, shade);
      if (state.ray.opacity >= f.params.sampling.ert) return true;
    }
  }
  return false;
}

bool cancelRequested(const FastRenderOptions& options) {
  return options.cancel && options.cancel->load(std::memory_order_relaxed);
}

// Scratch of one worker, reused from row to row. A ray's state is made when a visible group
// first needs it, so rays through empty space cost nothing.
template <class Sampler>
struct RowScratch {
  RowTiles tiles;
  std::vector<std::optional<RayState<Sampler>>> rays;
};

// The samples of one column's passage through a tile group. Returns true if the ray terminated.
template <bool Mip, class Sampler>
bool visitGroup(const Frame& f, const RowTiles& row, const GroupRun& group, RayState<Sampler>& state,
                std::uint64_t& samples) {
  if (maySkip(f.skipGroups, f, row.groupVisible[group.group], row.groupMaxDensity[group.group],
              state.mipMaximum))
    return false;
  for (std::uint32_t r = group.firstRun; r < group.endRun; ++r) {
    const TileRun& run = f.templates.runs[r];
    const long end = run.firstSample + run.count;
    if (end <= state.resumeAt) continue;
    if (maySkip(f.skipTiles, f, row.visible[run.tile], row.maxDensity[run.tile], state.mipMaximum))
      continue;
    samples += end - std::max(run.firstSample, state.resumeAt);
    if (sampleRun<Mip>(f, run, state)) return true;
  }
  return false;
}

// Renders one row group by group in front-to-back order (RayTemplates::visits), each ray keeping
// its state in between; returns false if cancelled part-way (checked every 4 groups).
template <bool Mip, class Sampler>
bool renderRow(const Frame& f, int y, RowScratch<Sampler>& scratch, Image& image, std::uint64_t& samples) {
  const double axisMm = f.view.rayOrigin(0, y)[f.view.axis];
  // Rows above or below the domain see nothing (the reference's slab test, see sampleRange).
  if (axisMm < -1e-9 || axisMm > f.view.extent[f.view.axis] + 1e-9) {
    std::fill_n(&image.at(0, y), f.view.width, glm::vec4(0.f));
    return true;
  }
  if (cancelRequested(f.options)) return false;
  classifyRow(f, axisMm / f.volume.spacing[f.view.axis], scratch.tiles);
  auto& rays = scratch.rays;
  rays.resize(f.view.width);
  for (auto& ray : rays) ray.reset();
  const RayTemplates& templates = f.templates;
  const bool mip = f.params.compositing == Compositing::mip;
  for (std::size_t rank = 0; rank + 1 < templates.rankBegin.size(); ++rank) {
    if (rank % 4 == 3 && cancelRequested(f.options)) return false;
    const std::int32_t group = templates.rankGroup[rank];
    if (!mip && maySkip(f.skipGroups, f, scratch.tiles.groupVisible[group], 0, 0.f)) continue;
    for (std::uint32_t v = templates.rankBegin[rank]; v < templates.rankBegin[rank + 1]; ++v) {
      const GroupVisit visit = templates.visits[v];
      auto& state = rays[visit.column];
      if (!state)
        state.emplace(RayState<Sampler>{RaySamples(f.volume, f.view, f.view.rayOrigin(int(visit.column), y)),
                                        RegionCursor(f.regionTables.regions, int(visit.column), y),
                                        Sampler(f.volume, f.rayStepQ)});
      else if (state->terminated) continue;
      state->terminated = visitGroup<Mip>(f, scratch.tiles, templates.groups[visit.groupRun], *state, samples);
    }
  }
  for (int x = 0; x < f.view.width; ++x) {
    if (!rays[x]) image.at(x, y) = Mip && templates.columnBegin[x] != templates.columnBegin[x + 1]
                                       ? mipPixel(0.f, f.params.mip) : glm::vec4(0.f);
    else image.at(x, y) = Mip ? mipPixel(rays[x]->mipMaximum, f.params.mip) : rays[x]->ray.pixel();
  }
  return true;
}

// Renders rows [first, end); returns false if cancelled.
template <bool Mip, class Sampler>
bool renderRows(const Frame& f, int first, int end, Image& image, std::uint64_t& samples) {
  RowScratch<Sampler> scratch;
  for (int y = first; y != end; ++y) {
    if (!renderRow<Mip>(f, y, scratch, image, samples)) return false;
    if (f.options.rowsDone) f.options.rowsDone->fetch_add(1, std::memory_order_relaxed);
  }
  return true;
}

using RowFunction = bool (*)(const Frame&, int, int, Image&, std::uint64_t&);

template <bool Mip>
RowFunction rowFunctionFor(Filter filter) {
  switch (filter) {
    case Filter::nearest: return renderRows<Mip, NearestRaySampler>;
    case Filter::mean: return renderRows<Mip, MeanRaySampler>;
    case Filter::trilinear: return renderRows<Mip, TrilinearRaySampler>;
  }
  return renderRows<Mip, NearestRaySampler>;
}

// The row renderer compiled for the frame's filter and compositing.
RowFunction rowFunctionFor(const RenderParams& params) {
  return params.compositing == Compositing::mip ? rowFunctionFor<true>(params.sampling.filter)
                                                 : rowFunctionFor<false>(params.sampling.filter);
}

// The frame's image: every pixel is written by its row, so recycled memory needs no clearing.
Image frameImage(const ViewGeometry& view, Image* recycle) {
  if (!recycle) return makeImage(view.width, view.height);
  Image image = std::move(*recycle);
  *recycle = Image{};
  image.width = view.width;
  image.height = view.height;
  image.pixels.resize(std::size_t(view.width) * view.height);
  return image;
}

// A table whose visibility query answers "visible in any region's TF" (only integratedVisible set).
TfTable unionVisibility(const RegionTables& tables) {
  TfTable any;
  for (int d = 0; d < kDensityLevels; ++d) {
    bool visible = false;
    for (const TfTable* table : {tables.regions ? tables.focus : nullptr,
                                 tables.regions ? tables.context : nullptr, tables.outside})
      visible = visible || (table && table->rgba[d].a > 0.f);
    any.integratedVisible[d + 1] = any.integratedVisible[d] + (visible ? 1 : 0);
  }
  return any;
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
  Frame f{volume, tiles, visibleTiles, params, options, tables, makeViewGeometry(volume, params),
          frameTables(tables, params.sampling.osd), {}};
  const TfTable anyRegion = unionVisibility(tables);
  f.anyRegionTf = &anyRegion;
  f.skipGroups = options.skipEmpty && options.skipGroups;
  f.skipTiles = options.skipEmpty && options.skipTiles;
  // Cell skipping pays only with several samples per cell: at osd 1 (about one sample per cell)
  // the test and leap cost more than the interpolation they save (`angioray bench`: medium with
  // trilinear 119 ms without, 134 ms with; high at osd 0.3: 964 ms without, 842 ms with).
  f.skipCells = options.skipEmpty && options.skipCells && params.sampling.osd < 0.75;
  f.rayStepQ = RaySamples(volume, f.view, glm::dvec3(0.0)).stepQ;
  f.templates = buildRayTemplates(volume, f.view, tiles, options.cancel);
  const double templateMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (cancelRequested(options)) {
    if (stats) *stats = {0, templateMs, true};
    return makeImage(f.view.width, f.view.height);
  }

  Image image = frameImage(f.view, options.recycle);
  const RowFunction renderRowsFn = rowFunctionFor(params);
  std::atomic<std::uint64_t> samples{0};
  std::atomic<bool> cancelled{false};
  tbb::parallel_for(tbb::blocked_range<int>(0, f.view.height), [&](const tbb::blocked_range<int>& rows) {
    std::uint64_t local = 0;
    if (!renderRowsFn(f, rows.begin(), rows.end(), image, local)) cancelled = true;
    samples += local;
  });
  if (stats) *stats = {samples.load(), templateMs, cancelled.load()};
  return image;
}

}  // namespace angio
