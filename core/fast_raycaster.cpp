#include "core/fast_raycaster.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/clip_interval.h"
#include "core/compositing.h"
#include "core/preintegration.h"
#include "core/ray_samplers.h"
#include "core/ray_templates.h"
#include "core/sample_batch.h"
#include "core/volume_sampling.h"
#include "core/voxel_grid.h"

namespace angio {

namespace {

struct Frame {
  const Volume& volume;  // the geometry; voxels are read through `voxels`
  VoxelGrid voxels;
  const SliceTiles& tiles;
  const std::vector<std::uint64_t>& visibleMasks;  // the classification's, for the filter's reach
  const RenderParams& params;
  const FastRenderOptions& options;
  const RegionTables& regionTables;
  const std::vector<std::uint16_t>& tileMaxDensity;  // the classification's, for MIP
  LabelTables labels;  // the tables' labels (as unlabelled voxels when it has none)
  ViewGeometry view;
  FrameTables tables;
  RayTemplates templates;
  // Pre-integrated classification (params.sampling.preintegrated, DVR), slot for slot with tables.
  const PreintegratedTables* segments = nullptr;

  glm::dvec3 rayStepQ{0.0};  // from one sample to the next, voxel units (RaySamples::stepQ)
  bool skipGroups = true, skipTiles = true, skipCells = true;  // FastRenderOptions, resolved
  bool shareRows = true;
  bool batchSamples = true;
  bool ownTfs = false;  // some label has its own TF
  // With ownTfs, for the sample batches: the outside TF's table and the labels' own, one after the
  // other (the batches' LaneTables point into it).
  std::vector<SampleTable> laneTableEntries;
  LaneTables laneTables;
  bool clipped = false;  // a crop box, clip plane or slab cuts the rays (params.clipping)
  // MIP through the window (mipPixel): a maximum up to mipBlack shows black, one from mipWhite on
  // white. A ray's maximum starts at mipBlack, so tiles, groups and cells no denser are skipped
  // (air and fat below a vessel window), and a ray is done once its maximum reaches mipWhite.
  float mipBlack = 0.f;
  float mipWhite = std::numeric_limits<float>::infinity();
  // Visible where any region's TF is: a cell hidden from it is hidden from every sample in it.
  const TfTable* anyRegionTf = nullptr;
  const std::vector<std::uint8_t>* pixels = nullptr;  // FastRenderOptions::pixels

  bool wanted(int x, int y) const { return !pixels || (*pixels)[std::size_t(y) * view.width + x] != 0; }
  bool rowWanted(int y) const {
    if (!pixels) return true;
    const auto row = pixels->begin() + std::ptrdiff_t(y) * view.width;
    return std::any_of(row, row + view.width, [](std::uint8_t p) { return p != 0; });
  }

  // The uncorrected TF of a region, for visibility queries (nullptr: clipped).
  const TfTable* tfOf(Region region) const {
    switch (region) {
      case Region::focus: return regionTables.regions ? regionTables.focus : nullptr;
      case Region::context: return regionTables.regions ? regionTables.context : nullptr;
      case Region::outside: return regionTables.outside;
    }
    return nullptr;
  }
  // The same for a sample whose nearest voxel has `label`.
  const TfTable* tfOf(Region region, int label) const {
    const TfTable* table = tfOf(region);
    const TfTable* own = labels.ownTf(label);
    return table && own ? own : table;
  }
};

// Per row: which tiles may hold a visible sample (DVR: a mask per tile group, bit groupBit(tile))
// or the largest density a sample can take there (MIP), over the slices the row's samples read.
// Rows reading the same slices share it.
struct RowTiles {
  SliceSpan span{0, -1};
  std::vector<std::uint64_t> groupMask;   // per tile group (DVR)
  std::vector<std::uint16_t> maxDensity;  // per tile (MIP)
  std::vector<std::uint16_t> groupMaxDensity;
};

void classifyRowMip(const Frame& f, RowTiles& row) {
  const std::size_t perSlice = f.tiles.tilesPerSlice();
  row.maxDensity.assign(perSlice, 0);
  for (int s = row.span.first; s <= row.span.last; ++s) {
    std::uint16_t* __restrict out = row.maxDensity.data();
    const std::uint16_t* __restrict in = f.tileMaxDensity.data() + perSlice * s;
    for (std::size_t t = 0; t < perSlice; ++t) out[t] = std::max(out[t], in[t]);
  }
  row.groupMaxDensity.assign(f.tiles.groupsPerSlice(), 0);
  for (std::size_t t = 0; t < perSlice; ++t) {
    std::uint16_t& group = row.groupMaxDensity[f.tiles.groupOf(int(t))];
    group = std::max(group, row.maxDensity[t]);
  }
}

void classifyRow(const Frame& f, double qa, RowTiles& row) {
  const SliceSpan span = slicesReadAt(f.tiles, qa, f.params.sampling.filter);
  if (span.first == row.span.first && span.last == row.span.last) return;
  row.span = span;
  if (f.params.compositing == Compositing::mip) {
    classifyRowMip(f, row);
    return;
  }
  const std::size_t groups = f.tiles.groupsPerSlice();
  row.groupMask.assign(groups, 0);
  for (int s = span.first; s <= span.last; ++s) {
    std::uint64_t* __restrict out = row.groupMask.data();
    const std::uint64_t* __restrict in = f.visibleMasks.data() + groups * s;
    for (std::size_t g = 0; g < groups; ++g) out[g] |= in[g];
  }
}

// Rows whose samples read the same voxels: consecutive rows with the same cell base (trilinear)
// or nearest voxel (nearest, mean) along the rotation axis a. Their in-plane sample positions are
// the same (the rendering model's rays differ only by v e_a from row to row), so they meet the
// same cells in the same order: one pass along each column loads a cell's corners, tests its
// transparency and computes its gradients once for all of them, and each row only interpolates
// with its own fraction along a. At the high level (isd 0.5) several rows share a slice pair.
constexpr int kMaxBundleRows = 4;

struct RowBundle {
  int firstRow = 0;
  int rows = 1;
  bool outside = false;  // above or below the domain: black (the reference's slab test)
  // Rays that differ: every row for trilinear or with regions; otherwise the rows' rays are
  // identical (same voxels, same TF) and the first row's pixels are copied to the others.
  int lanes = 1;
  std::array<float, kMaxBundleRows> fracA{};  // each row's cell fraction along a (cellAt)
  double qa = 0;                              // the first row's axis coordinate, voxel units
};

// Where row y's rays are along a, and what decides the voxels they read there: cellAt's base
// (trilinear) or nearestVoxel's index (nearest, mean), from the row's first ray origin as
// RaySamples computes it (q = origin / spacing; every ray of a row has the same q along a).
struct RowPlace {
  bool outside = false;  // above or below the domain (the reference's slab test, see sampleRange)
  double qa = 0;         // voxel units
  int key = -1;          // rows with the same key read the same voxels along a
  float fracA = 0;       // cellAt's fraction along a
};

RowPlace rowPlace(const Frame& f, int y) {
  const int a = f.view.axis;
  const glm::dvec3 origin = f.view.rayOrigin(0, y);
  const glm::dvec3 q = origin / f.volume.spacing;
  const Cell cell = cellAt(f.volume, q);
  RowPlace place;
  place.outside = origin[a] < -1e-9 || origin[a] > f.view.extent[a] + 1e-9;
  place.qa = q[a];
  place.key =
      f.params.sampling.filter == Filter::trilinear ? cell.base[a] : nearestVoxel(f.volume, q)[a];
  place.fracA = cell.frac[a];
  return place;
}

// Whether the clipping cuts every ray of a column the same way whatever its row: rows differ by
// v e_a, so a crop box (whose bounds along a may pass between them) or a plane tilted towards a
// cuts them apart; a plane facing the viewer, one parallel to a and the slab do not.
bool rowsClippedAlike(const ViewClipping& clipping, int axis) {
  const auto& plane = clipping.plane;
  return !clipping.crop && (!plane || plane->facingViewer || plane->normal[axis] == 0);
}

std::vector<RowBundle> rowBundles(const Frame& f) {
  const int maxRows = f.shareRows ? kMaxBundleRows : 1;
  const bool distinctRays = f.params.sampling.filter == Filter::trilinear || f.regionTables.regions ||
                            !rowsClippedAlike(f.params.clipping, f.view.axis);
  std::vector<RowBundle> bundles;
  int lastKey = -1;
  for (int y = 0; y < f.view.height; ++y) {
    if (!f.rowWanted(y)) {  // not rendered, and the rows around it are no longer consecutive
      lastKey = -1;
      continue;
    }
    const RowPlace place = rowPlace(f, y);
    RowBundle* last = bundles.empty() ? nullptr : &bundles.back();
    if (last && !place.outside && !last->outside && place.key == lastKey && last->rows < maxRows &&
        last->firstRow + last->rows == y) {
      last->fracA[last->rows++] = place.fracA;
      last->lanes = distinctRays ? last->rows : 1;
      continue;
    }
    RowBundle bundle;
    bundle.firstRow = y;
    bundle.outside = place.outside;
    bundle.qa = place.qa;
    bundle.fracA[0] = place.fracA;
    bundles.push_back(bundle);
    lastKey = place.outside ? -1 : place.key;
  }
  return bundles;
}

// One row's ray in a bundle.
struct Lane {
  RegionCursor regions;
  RayAccumulator ray;
  float mipMaximum = 0.f;
  // Samples before it are in a clipped region or before the view clipping's interval.
  long resumeAt = std::numeric_limits<long>::min();
  long endAt = std::numeric_limits<long>::max();  // the first sample after the clipping's interval
  bool shows = true;  // some sample lies in the domain and the clipping's interval (MIP: not black)
  bool done = false;  // terminated early, or nothing more shown
  long firstEvaluated = -1;  // profiling: the lane's first reconstructed sample
  // Pre-integration: the density of the lane's last evaluated sample, and which sample that was;
  // samples up to it are done (a run's extension, see visitGroup, may have taken the next run's first).
  float front = 0.f;
  long frontAt = std::numeric_limits<long>::min();
  float frontShade = 1.f;  // the shading factor of sample frontShadeAt (computed where visible)
  long frontShadeAt = std::numeric_limits<long>::min();
};

// What the rays of one column of a bundle carry from one tile group to the next.
template <class Sampler>
struct BundleRay {
  BundleRay(const RaySamples& positions, const Sampler& sampler, int live)
      : positions(positions), sampler(sampler), live(live) {}

  RaySamples positions;  // the first row's; the in-plane part is every row's
  Sampler sampler;
  std::array<Lane, kMaxBundleRows> lanes;
  int live = 1;                   // lanes not done
  RayProfile* profile = nullptr;  // the worker's counts when profiling (Mode::profile)
  // The view clipping's samples of every lane: [clipBegin, clipEnd), and the first endAt of a
  // live lane (after it that lane is finished).
  long clipBegin = std::numeric_limits<long>::min();
  long clipEnd = std::numeric_limits<long>::max();
  long nextEnd = std::numeric_limits<long>::max();
  long domainEnd = std::numeric_limits<long>::max();  // pre-integration: after the ray's last sample
  // Pre-integration: the last sample of the last hidden cell leapt over, and its corners' density
  // range, which holds every lane's density there.
  long hiddenAt = std::numeric_limits<long>::min();
  glm::ivec2 hiddenRange{0};

  // The first sample any live lane still needs.
  long resumeAt(int lanes) const {
    long first = std::numeric_limits<long>::max();
    for (int l = 0; l < lanes; ++l)
      if (!this->lanes[l].done) first = std::min(first, this->lanes[l].resumeAt);
    return first;
  }
  // MIP: a sample can change some pixel only above the smallest maximum of the live lanes.
  float mipFloor(int lanes) const {
    float floor = std::numeric_limits<float>::max();
    for (int l = 0; l < lanes; ++l)
      if (!this->lanes[l].done) floor = std::min(floor, this->lanes[l].mipMaximum);
    return floor;
  }
  void finish(Lane& lane) {
    lane.done = true;
    --live;
  }
  // Before sample k: finishes the lanes whose clip interval ends there.
  void finishEnded(long k, int lanes) {
    nextEnd = std::numeric_limits<long>::max();
    for (int l = 0; l < lanes; ++l) {
      Lane& lane = this->lanes[l];
      if (lane.done) continue;
      if (lane.endAt <= k) finish(lane);
      else nextEnd = std::min(nextEnd, lane.endAt);
    }
  }
};

// What the inner loop is compiled for: MIP or DVR, with or without VesselGlyph regions, with or
// without labels that render differently from unlabelled voxels.
template <bool Mip, bool Regions, bool Labels, bool Profile = false>
struct Compiled {
  static constexpr bool mip = Mip;
  static constexpr bool regions = Regions;
  static constexpr bool labels = Labels;
  static constexpr bool profile = Profile;  // count where the samples go (core/ray_profile.h)
};

// Profiling counts per ray, so rows that share one lane (identical rays) count once each.
int raysPerLane(const RowBundle& bundle) { return bundle.rows / bundle.lanes; }

void countSample(const RowBundle& bundle, long k, float opacity, Lane& lane, RayProfile& profile) {
  const int rays = raysPerLane(bundle);
  if (lane.firstEvaluated < 0) lane.firstEvaluated = k;
  profile.evaluated += rays;
  if (opacity > 0.f) profile.visible += rays;
  if (opacity > 0.f && opacity < RayProfile::kFaintOpacity) profile.faint += rays;
}

void countTermination(const RowBundle& bundle, long k, const Lane& lane, RayProfile& profile) {
  const int rays = raysPerLane(bundle);
  profile.terminatedRays += rays;
  profile.terminatedDepth += std::uint64_t(k - lane.firstEvaluated + 1) * rays;
}

// Pre-integration: the segment from sample k - 1 to k of lane l, classified with sample k's TF
// (core/preintegration.h). The front is the lane's last evaluated sample, or read where the lane
// did not evaluate k - 1 (skipped, clipped, or before the ray's first sample), as the reference does.
template <class Sampler>
glm::vec4 preintegratedSegment(const Frame& f, const RowBundle& bundle, int l, long k, Region region,
                               int label, float back, BundleRay<Sampler>& b) {
  Lane& lane = b.lanes[l];
  const float front =
      lane.frontAt == k - 1 ? lane.front : b.sampler.densityAt(b.positions.at(k - 1), bundle.fracA[l]);
  lane.front = back;
  lane.frontAt = k;
  return f.segments->of(region, label, f.tables).segment(front, back);
}

// Pre-integration with shading: a segment's emission is shaded by the mean of its ends' shading
// factors (core/preintegration.h); the front's is the lane's last one, or read at sample k - 1.
template <class Sampler>
float segmentShade(const Frame& f, const RowBundle& bundle, int l, long k, float backShade,
                   BundleRay<Sampler>& b) {
  Lane& lane = b.lanes[l];
  const float frontShade =
      lane.frontShadeAt == k - 1
          ? lane.frontShade
          : shadingFactor(f.params.shading, b.sampler.gradientAt(b.positions.at(k - 1), bundle.fracA[l]),
                          glm::vec3(f.view.viewDir));
  lane.frontShade = backShade;
  lane.frontShadeAt = k;
  return 0.5f * (frontShade + backShade);
}

// MIP: the lane's maximum raised to `density` if above it; the lane is done once the window shows
// its maximum white.
template <class Sampler>
void raiseMaximum(const Frame& f, Lane& lane, float density, BundleRay<Sampler>& b) {
  lane.mipMaximum = std::max(lane.mipMaximum, density);
  if (lane.mipMaximum >= f.mipWhite) b.finish(lane);
}

// One sample k of one lane, after the bundle's sampler moved to it.
template <class Mode, class Sampler>
void sampleLane(const Frame& f, const RowBundle& bundle, int l, long k, BundleRay<Sampler>& b) {
  Lane& lane = b.lanes[l];
  const double t = double(k) * f.view.sampleMm;
  const Region region = Mode::regions ? lane.regions.at(t) : Region::outside;
  // Only own TFs need the sample's label; hidden labels are all in the sampler's reads.
  int label = 0;
  if constexpr (Mode::labels && !Mode::mip)
    if (f.ownTfs) label = b.sampler.label(bundle.fracA[l]);
  const SampleTable* table = Mode::labels ? f.tables.of(region, label) : f.tables.of(region);
  if (Mode::regions && !table) {
    // A clipped region (VesselGlyph): leap to just before its end. The sample there is
    // classified as every other one, so the leap needs no exact division.
    const double change = lane.regions.nextChange(t);
    if (change == std::numeric_limits<double>::infinity()) {
      b.finish(lane);  // nothing more shown
      return;
    }
    lane.resumeAt = std::max(k + 1, long(change / f.view.sampleMm) - 1);
    return;
  }
  Sampler& sampler = b.sampler;
  if constexpr (Mode::mip) {
    raiseMaximum(f, lane, sampler.density(bundle.fracA[l]), b);
  } else {
    // (Without regions the sampler's cell already passed this test for every lane. A
    // pre-integrated segment reaches back to the sample before: sampleSpan tests that.)
    if (Mode::regions && f.skipCells && !f.segments && !sampler.mayBeVisible(*f.tfOf(region, label)))
      return;
    const float density = sampler.density(bundle.fracA[l]);
    const glm::vec4 rgba = f.segments ? preintegratedSegment(f, bundle, l, k, region, label, density, b)
                                      : (*table)[tableIndex(density)];
    if constexpr (Mode::profile) countSample(bundle, k, rgba.a, lane, *b.profile);
    if (rgba.a <= 0.f) return;
    float shade = f.params.shading.enabled
                      ? shadingFactor(f.params.shading, sampler.gradient(bundle.fracA[l]),
                                      glm::vec3(f.view.viewDir))
                      : 1.f;
    if (f.segments && f.params.shading.enabled) shade = segmentShade(f, bundle, l, k, shade, b);
    lane.ray.add(rgba, shade);
    if (lane.ray.opacity >= f.params.sampling.ert) {
      if constexpr (Mode::profile) countTermination(bundle, k, lane, *b.profile);
      b.finish(lane);
    }
  }
}

// Pre-integration: sample k lies in a cell the TFs hide. Its segment is hidden too when the
// densities from sample k - 1 into the cell are, for every lane that needs it: k - 1 was the lane's
// last evaluated sample, or the last of a hidden cell leapt over (its density in that cell's range).
template <class Sampler>
bool frontsHidden(const Frame& f, const RowBundle& bundle, long k, const BundleRay<Sampler>& b) {
  glm::ivec2 range = b.sampler.densityRange();
  for (int l = 0; l < bundle.lanes; ++l) {
    const Lane& lane = b.lanes[l];
    if (lane.done || k < lane.resumeAt || k <= lane.frontAt) continue;
    glm::ivec2 front;
    if (lane.frontAt == k - 1) front = glm::ivec2(tableIndex(lane.front));
    else if (b.hiddenAt == k - 1) front = b.hiddenRange;
    else return false;
    range = {std::min(range.x, front.x), std::max(range.y, front.y)};
  }
  return !f.anyRegionTf->anyVisible(range.x, range.y);
}

// The samples [first, stop) of one tile run, composited into each lane's ray (DVR) or maximum
// (MIP); returns the sample reached (>= stop, or where every lane was done). Samples the sampler
// proves invisible for every lane (or, in MIP, not above any lane's maximum) are skipped without
// interpolation; they could not change a pixel.
template <class Mode, class Sampler>
long sampleEach(const Frame& f, const RowBundle& bundle, long first, long stop, BundleRay<Sampler>& b) {
  const bool skip = f.skipCells;
  const int lanes = bundle.lanes;
  Sampler& sampler = b.sampler;
  long k = first;
  for (; k < stop; ++k) {
    sampler.moveTo(b.positions.at(k));
    if constexpr (Mode::mip) {
      if (skip && sampler.maxDensity() <= b.mipFloor(lanes)) {
        k += sampler.samplesLeftInCell();
        continue;
      }
    } else {
      if (skip && !sampler.mayBeVisible(*f.anyRegionTf) &&
          (!f.segments || frontsHidden(f, bundle, k, b))) {
        if constexpr (Mode::profile)
          b.profile->skippedByCells +=
              std::uint64_t(std::min<long>(sampler.samplesLeftInCell() + 1, stop - k)) * b.live *
              raysPerLane(bundle);
        b.hiddenAt = k + sampler.samplesLeftInCell();
        b.hiddenRange = sampler.densityRange();
        k = b.hiddenAt;
        continue;
      }
    }
    for (int l = 0; l < lanes; ++l)
      if (!b.lanes[l].done && k >= b.lanes[l].resumeAt && k > b.lanes[l].frontAt)
        sampleLane<Mode>(f, bundle, l, k, b);
    if (b.live == 0) return k;
    // Every lane in a clipped stretch: leap to the first sample one of them needs.
    if constexpr (Mode::regions) {
      const long next = b.resumeAt(lanes);
      if (next > k + 1) k = next - 1;
    }
  }
  return k;
}

// Samplers whose samples go through the batches (core/sample_batch.h): trilinear and mean.
// Nearest is not batched: one read per sample leaves too little to share, and its frames took
// 9 % longer in batches (`angioray bench`, "no sample batches" at the medium level).
template <class Sampler>
constexpr bool kBatchedSampler = std::is_same_v<Sampler, TrilinearRaySampler<typename Sampler::Read>> ||
                                 std::is_same_v<Sampler, MeanRaySampler<typename Sampler::Read>>;

// Whether a span's samples go through the batches: DVR or MIP, not pre-integrated. Labels may be
// hidden, or have TFs of their own (each lane picks its table: LaneTables); DVR may have VesselGlyph
// regions (each lane its region's table) but not with those labels. The mean's rows are one lane
// (their rows read the same voxels and are copied).
template <class Mode>
bool batchable(const Frame& f, const RowBundle& bundle) {
  return f.batchSamples && !(Mode::regions && (Mode::mip || f.ownTfs)) && !f.segments &&
         (f.params.sampling.filter == Filter::trilinear || bundle.lanes == 1);
}

using BundleBatch = SampleBatch<kMaxBundleRows>;
using LanesTables = BatchTables<kMaxBundleRows>;

// The sampler's voxel reader: the frame's label mask, or the plain density.
template <class Read>
Read densityReader(const Frame& f) {
  if constexpr (std::is_same_v<Read, MaskedDensity>) return f.labels.density();
  else return Read{};
}

// The batch's samples of every lane reconstructed and classified with the sampler's filter; false
// where the scalar path must take them (the volume's faces).
template <class Sampler>
bool classifyBatch(const Frame& f, const RowBundle& bundle, const BundleRay<Sampler>& b,
                   const LanesTables& tables, long first, int count, BundleBatch& batch) {
  if constexpr (std::is_same_v<Sampler, MeanRaySampler<typename Sampler::Read>>)
    return classifyMeanSamples(f.voxels, densityReader<typename Sampler::Read>(f), b.positions, tables,
                               first, count, batch);
  else
    return classifyTrilinearSamples(f.voxels, densityReader<typename Sampler::Read>(f), b.positions,
                                    tables, first, count, f.view.axis, bundle.fracA.data(), bundle.lanes,
                                    batch);
}

// VesselGlyph: the first sample from `at` on (or `stop`) that may lie in a rendered region for some
// lane not done; before it every lane's region is not rendered (sampleLane leaps the same way, to
// just before a region's end).
template <class Sampler>
long firstRendered(const Frame& f, const RowBundle& bundle, const BundleRay<Sampler>& b, long at,
                   long stop) {
  const double t = double(at) * f.view.sampleMm;
  long first = stop;
  for (int l = 0; l < bundle.lanes; ++l) {
    if (b.lanes[l].done) continue;
    RegionCursor probe = b.lanes[l].regions;
    if (f.tables.of(probe.at(t))) return at;
    const double change = probe.nextChange(t);
    if (change != std::numeric_limits<double>::infinity())
      first = std::min(first, std::max(at, long(change / f.view.sampleMm) - 1));
  }
  return first;
}

// VesselGlyph: each lane's table for the batch's samples [first, first + count) (BatchTables),
// false where a lane's region changes inside the batch (the scalar path takes it). The lanes'
// cursors are probed on copies: a batch is classified ahead of the one before it, which may still
// go to the scalar path and walk the cursors from where they are.
template <class Sampler>
bool regionTables(const Frame& f, const RowBundle& bundle, const BundleRay<Sampler>& b, long first,
                  int count, LanesTables& tables) {
  const double begin = double(first) * f.view.sampleMm;
  const double last = double(first + count - 1) * f.view.sampleMm;
  for (int l = 0; l < bundle.lanes; ++l) {
    RegionCursor probe = b.lanes[l].regions;
    const Region region = probe.at(begin);
    if (!(last < probe.nextChange(begin))) return false;
    const SampleTable* table = f.tables.of(region);
    tables.row[l] = table ? table->data() : nullptr;
  }
  return true;
}

// LaneTables for the frame's labels with TFs of their own (no regions: the outside TF).
void buildLaneTables(Frame& f) {
  f.laneTableEntries = {f.tables.outside};
  f.laneTableEntries.insert(f.laneTableEntries.end(), f.tables.ownTables.begin(),
                            f.tables.ownTables.end());
  f.laneTables.entries = f.laneTableEntries.front().data();
  for (int label = 0; label < kLabelCount; ++label)
    f.laneTables.start[label] = (f.tables.ownSlot[label] + 1) * kDensityLevels;  // slot -1: 0
}

// The first of the batch's samples (from `first`, `count` of them) that the lane needs: its clip
// interval may start inside the batch or after it (then `count`).
int firstNeeded(const Lane& lane, long first, int count) {
  // (resumeAt may be the lowest long: compared before it is subtracted.)
  return lane.resumeAt <= first ? 0 : int(std::min<long>(lane.resumeAt - first, count));
}

// The lanes' visible samples of a batch that they still need: none of a lane that is done, none
// before its first sample (the view clipping). Returns their union.
template <class Sampler>
std::uint32_t neededSamples(const RowBundle& bundle, const BundleRay<Sampler>& b, BundleBatch& batch) {
  std::uint32_t any = 0;
  for (int l = 0; l < bundle.lanes; ++l) {
    const Lane& lane = b.lanes[l];
    std::uint32_t& visible = batch.rows[l].visible;
    const int skip = firstNeeded(lane, batch.first, kBatchSamples);
    visible = lane.done ? 0 : visible >> skip << skip;
    any |= visible;
  }
  return any;
}

// Profiling: lane l's samples of the batch from its first needed one up to `last`, evaluated.
template <class Sampler>
void countBatch(const RowBundle& bundle, const BundleBatch& batch, int l, int last,
                BundleRay<Sampler>& b) {
  Lane& lane = b.lanes[l];
  for (int j = firstNeeded(lane, batch.first, kBatchSamples); j <= last; ++j)
    countSample(bundle, batch.first + j, batch.rows[l].opacity[j], lane, *b.profile);
}

// The shading factors of a classified batch's samples for every lane, computed in lanes from the
// cells the trilinear filter read (core/sample_batch.h shadeRows: the scalar sampler's bits); false
// where they are computed one by one: cells at a flat volume's faces, and the mean filter (in lanes
// from the neighbours it read, fast frames did not gain: `angioray bench`, 24 angles, 3 rounds).
// A batch's visible samples come in runs (on the realistic phantom at the high level a row's batch
// with any visible sample has 5 of 8 visible on average), so shading all eight lanes wastes little.
template <class Sampler>
bool shadeBatch(const Frame& f, const RowBundle& bundle, const BundleBatch& batch,
                const glm::vec3& viewDir,
                std::array<std::array<float, kBatchSamples>, kMaxBundleRows>& shades) {
  if constexpr (std::is_same_v<Sampler, TrilinearRaySampler<typename Sampler::Read>>) {
    return shadeRows(f.voxels, densityReader<typename Sampler::Read>(f), batch, f.view.axis,
                     bundle.fracA.data(), bundle.lanes, f.params.shading, viewDir, shades);
  } else {
    return false;
  }
}

// sampleEach for DVR: eight samples reconstructed, classified (and with the trilinear filter
// shaded) at once for every lane of the bundle, then the visible ones composited in ray order; the
// same operations on the same values, so the same bits. Samples in cells the TF hides are
// classified with the others, not leapt over (no cell test); batches at the volume's faces, and
// with VesselGlyph regions batches in which a lane's region changes, are taken one by one.
template <class Mode, class Sampler>
long sampleBatches(const Frame& f, const RowBundle& bundle, long first, long stop,
                   BundleRay<Sampler>& b) {
  // Every lane's table: the outside TF's, or with labels that have TFs of their own the tables one
  // after the other (LaneTables); with VesselGlyph regions each batch's own (regionTables).
  LanesTables fixed;
  if (Mode::labels && f.ownTfs) {
    fixed.own = &f.laneTables;
    fixed.row.fill(f.laneTables.entries);
  } else if (!Mode::regions) {
    fixed.row.fill(f.tables.of(Region::outside)->data());
  }
  const glm::vec3 viewDir(f.view.viewDir);
  // Two batches in flight: the next one is classified before this one's visible samples are
  // composited, so its reads overlap the compositing's branches instead of waiting behind them.
  std::array<BundleBatch, 2> batches;
  std::array<LanesTables, 2> tables;
  std::array<bool, 2> classified{};
  const auto countAt = [&](long k) { return int(std::min<long>(kBatchSamples, stop - k)); };
  const auto classify = [&](long at, int slot) {
    if constexpr (Mode::regions) {
      if (!regionTables(f, bundle, b, at, countAt(at), tables[slot])) return false;
    } else {
      tables[slot] = fixed;
    }
    return classifyBatch(f, bundle, b, tables[slot], at, countAt(at), batches[slot]);
  };
  // With regions a batch starts where some lane's region is rendered, as sampleEach leaps.
  const auto startAt = [&](long k) { return Mode::regions ? firstRendered(f, bundle, b, k, stop) : k; };
  const long start = startAt(first);
  if (start < stop) classified[0] = classify(start, 0);
  long next = stop;
  for (long k = start, n = 0; k < stop; k = next, ++n) {
    const int count = countAt(k);
    next = startAt(k + count);
    if (next < stop) classified[(n + 1) % 2] = classify(next, int((n + 1) % 2));
    BundleBatch& batch = batches[n % 2];
    const LanesTables& batchTables = tables[n % 2];
    if (!classified[n % 2]) {
      const long reached = sampleEach<Mode>(f, bundle, k, k + count, b);
      if (b.live == 0) return reached;
      continue;
    }
    [[maybe_unused]] std::array<int, kMaxBundleRows> last;  // profiling: each lane's last evaluated
    if constexpr (Mode::profile)
      for (int l = 0; l < bundle.lanes; ++l) last[l] = b.lanes[l].done ? -1 : count - 1;
    const std::uint32_t needed = neededSamples(bundle, b, batch);
    std::array<std::array<float, kBatchSamples>, kMaxBundleRows> shades;
    const bool shadedInLanes = needed != 0 && f.params.shading.enabled &&
                               shadeBatch<Sampler>(f, bundle, batch, viewDir, shades);
    for (std::uint32_t any = needed; any != 0; any &= any - 1) {
      const int j = std::countr_zero(any);
      if (f.params.shading.enabled && !shadedInLanes) b.sampler.moveTo(b.positions.at(k + j));
      for (int l = 0; l < bundle.lanes; ++l) {
        Lane& lane = b.lanes[l];
        if (lane.done || !(batch.rows[l].visible >> j & 1)) continue;
        const float shade =
            !f.params.shading.enabled ? 1.f
            : shadedInLanes
                ? shades[l][j]
                : shadingFactor(f.params.shading, b.sampler.gradient(bundle.fracA[l]), viewDir);
        lane.ray.add(batchTables.row[l][batch.rows[l].entry[j]], shade);
        if (lane.ray.opacity < f.params.sampling.ert) continue;
        if constexpr (Mode::profile) {
          countBatch(bundle, batch, l, j, b);
          countTermination(bundle, k + j, lane, *b.profile);
          last[l] = -1;
        }
        b.finish(lane);
      }
      if (b.live == 0) return k + j;
    }
    if constexpr (Mode::profile)
      for (int l = 0; l < bundle.lanes; ++l)
        if (last[l] >= 0) countBatch(bundle, batch, l, last[l], b);
  }
  return stop;
}

// MIP: each lane's densities of the batch's samples (trilinear: per row; mean: one lane); false
// where the scalar path must take them.
template <class Sampler>
bool batchDensities(const Frame& f, const RowBundle& bundle, const BundleRay<Sampler>& b, long first,
                    int count, std::array<FloatLanes, kMaxBundleRows>& densities) {
  const auto read = densityReader<typename Sampler::Read>(f);
  if constexpr (std::is_same_v<Sampler, MeanRaySampler<typename Sampler::Read>>)
    return meanDensities(f.voxels, read, b.positions, first, count, densities[0]);
  else
    return trilinearRowDensities(f.voxels, read, b.positions, first, count, f.view.axis,
                                 bundle.fracA.data(), bundle.lanes,
                                 [&](int r, const FloatLanes& d) { densities[r] = d; });
}

// sampleEach for MIP: eight samples of every lane reconstructed at once, and each lane's maximum
// raised by the largest of those it needs (from its first sample on). A maximum does not depend on
// the order, so the bits are one by one's; a lane that reaches the window's white is done.
template <class Mode, class Sampler>
long mipBatches(const Frame& f, const RowBundle& bundle, long first, long stop, BundleRay<Sampler>& b) {
  std::array<FloatLanes, kMaxBundleRows> densities;
  for (long k = first; k < stop; k += kBatchSamples) {
    const int count = int(std::min<long>(kBatchSamples, stop - k));
    if (!batchDensities(f, bundle, b, k, count, densities)) {
      const long reached = sampleEach<Mode>(f, bundle, k, k + count, b);
      if (b.live == 0) return reached;
      continue;
    }
    for (int l = 0; l < bundle.lanes; ++l) {
      Lane& lane = b.lanes[l];
      if (lane.done) continue;
      raiseMaximum(f, lane, largestDensity(densities[l], firstNeeded(lane, k, count), count), b);
    }
    if (b.live == 0) return k + count - 1;
  }
  return stop;
}

// The samples [first, stop) of one tile run (sampleEach), in batches where they can be.
template <class Mode, class Sampler>
long sampleSpan(const Frame& f, const RowBundle& bundle, long first, long stop, BundleRay<Sampler>& b) {
  if constexpr (kBatchedSampler<Sampler>) {
    if (batchable<Mode>(f, bundle)) {
      if constexpr (Mode::mip) return mipBatches<Mode>(f, bundle, first, stop, b);
      else return sampleBatches<Mode>(f, bundle, first, stop, b);
    }
  }
  return sampleEach<Mode>(f, bundle, first, stop, b);
}

// The samples [first, end) of one tile run (or of consecutive ones); returns true when every lane
// is done, and then `doneAt`, the sample where the last one was. Lanes whose clip interval ends
// inside it are finished there: each span runs up to the next such end (without clipping there
// is none, and the run is one span).
template <class Mode, class Sampler>
bool sampleRun(const Frame& f, const RowBundle& bundle, long first, long end, BundleRay<Sampler>& b,
               long& doneAt) {
  for (long k = first;;) {
    doneAt = k = sampleSpan<Mode>(f, bundle, k, std::min(end, b.nextEnd), b);
    if (b.live == 0) return true;
    if (k >= end) return false;
    b.finishEnded(k, bundle.lanes);
    if (b.live == 0) return true;
  }
}

bool cancelRequested(const FastRenderOptions& options) {
  return options.cancel && options.cancel->load(std::memory_order_relaxed);
}

// Scratch of one worker, reused from bundle to bundle. A column's state is made when a visible
// group first needs it, so rays through empty space cost nothing.
template <class Sampler>
struct RowScratch {
  RowTiles tiles;
  std::vector<std::optional<BundleRay<Sampler>>> rays;
  std::vector<std::uint8_t> columns;  // with FastRenderOptions::pixels: a row of the bundle wants it
  RayProfile profile;                 // Mode::profile: this worker's counts
};

// With FastRenderOptions::pixels: the columns with a wanted pixel in some row of the bundle.
template <class Sampler>
void markWantedColumns(const Frame& f, const RowBundle& bundle, RowScratch<Sampler>& scratch) {
  if (!f.pixels) return;
  scratch.columns.assign(f.view.width, 0);
  for (int r = 0; r < bundle.rows; ++r)
    for (int x = 0; x < f.view.width; ++x) scratch.columns[x] |= f.wanted(x, bundle.firstRow + r);
}

// MIP: may the tile (or group) change a pixel of the bundle's column, that is, hold something
// denser than the smallest maximum so far?
template <class Sampler>
bool mayRaiseMaximum(std::uint16_t maxDensity, const BundleRay<Sampler>& b, int lanes) {
  return float(maxDensity) > b.mipFloor(lanes);
}

// Profiling: the samples of tile runs [first, end) skipped for every live lane.
template <class Sampler>
void countSkippedRuns(const Frame& f, const RowBundle& bundle, std::uint32_t first, std::uint32_t end,
                      BundleRay<Sampler>& b) {
  for (std::uint32_t r = first; r < end; ++r)
    b.profile->skippedByTiles += std::uint64_t(f.templates.runs[r].count) * b.live * raysPerLane(bundle);
}

// After the runs [firstRun, lastRun] (consecutive) were sampled up to sample `reached`: the end of
// the run holding it, so the samples of runs never entered are not counted.
long enteredRunsEnd(const Frame& f, std::uint32_t firstRun, std::uint32_t lastRun, long reached) {
  for (std::uint32_t r = firstRun; r <= lastRun; ++r) {
    const TileRun& run = f.templates.runs[r];
    if (reached < run.firstSample + run.count) return run.firstSample + run.count;
  }
  const TileRun& last = f.templates.runs[lastRun];
  return last.firstSample + last.count + (f.segments ? 1 : 0);
}

// The samples of one column's passage through a tile group. Returns true if every lane is done.
// (DVR: the caller has already skipped the groups no ray sees in this bundle; here the column
// skips the group if none of the tiles it crosses there is visible, one test of two masks.)
template <class Mode, class Sampler>
bool visitGroup(const Frame& f, const RowBundle& bundle, const RowTiles& row, const GroupRun& group,
                BundleRay<Sampler>& b, std::uint64_t& samples) {
  std::uint64_t shown = ~std::uint64_t{0};  // DVR: the crossed tiles that may be visible
  if constexpr (Mode::mip) {
    if (f.skipGroups && !mayRaiseMaximum(row.groupMaxDensity[group.group], b, bundle.lanes))
      return false;
  } else if (f.skipTiles) {
    shown = group.crossed & row.groupMask[group.group];
    if (shown == 0) {
      if constexpr (Mode::profile) countSkippedRuns(f, bundle, group.firstRun, group.endRun, b);
      return false;
    }
  }
  for (std::uint32_t r = group.firstRun; r < group.endRun; ++r) {
    const TileRun& run = f.templates.runs[r];
    const bool hidden = Mode::mip
                            ? f.skipTiles && !mayRaiseMaximum(row.maxDensity[run.tile], b, bundle.lanes)
                            : !(shown >> run.bit & 1);
    if (hidden) {
      if constexpr (Mode::profile) countSkippedRuns(f, bundle, r, r + 1, b);
      continue;
    }
    if (run.firstSample >= b.clipEnd) {  // beyond every lane's clip interval
      b.finishEnded(run.firstSample, bundle.lanes);
      return true;
    }
    // DVR: the visible runs that follow it without a gap are sampled with it, as one span (longer
    // spans fill the batches of sampleBatches).
    const std::uint32_t firstRun = r;
    long last = run.firstSample + run.count;
    if constexpr (!Mode::mip)
      for (; r + 1 < group.endRun; ++r) {
        const TileRun& next = f.templates.runs[r + 1];
        if (!(shown >> next.bit & 1) || next.firstSample != last) break;
        last += next.count;
      }
    // Pre-integration: a visible run also takes the next run's first sample, whose segment starts
    // here; hidden runs after it then hold only hidden segments (both ends in hidden tiles).
    const long runEnd = last + (f.segments ? 1 : 0);
    const long end = std::min({runEnd, b.clipEnd, b.domainEnd});
    long first = std::max(run.firstSample, b.clipBegin);
    if constexpr (Mode::regions) first = std::max(first, b.resumeAt(bundle.lanes));
    if (end <= first) continue;
    long doneAt = 0;
    const bool done = sampleRun<Mode>(f, bundle, first, end, b, doneAt);
    // The samples of the runs entered (a run is entered whole, as if sampled alone).
    const long entered = done ? std::min(end, enteredRunsEnd(f, firstRun, r, doneAt)) : end;
    samples += std::uint64_t(entered - first) * bundle.rows;
    if (done) return true;
  }
  return false;
}

// Each lane's samples as the reference takes them (clippedSampleRange of the lane's own ray); a
// lane with none is done before it starts.
template <class Sampler>
void clipLanes(const Frame& f, const RowBundle& bundle, int x, BundleRay<Sampler>& b) {
  b.clipBegin = std::numeric_limits<long>::max();
  b.clipEnd = std::numeric_limits<long>::min();
  for (int l = 0; l < bundle.lanes; ++l) {
    Lane& lane = b.lanes[l];
    const SampleRange range =
        clippedSampleRange(f.view, f.params.clipping, f.view.rayOrigin(x, bundle.firstRow + l));
    lane.resumeAt = range.first;
    lane.endAt = range.last + 1;
    lane.shows = !range.empty();
    if (!lane.shows) {
      b.finish(lane);
      continue;
    }
    b.clipBegin = std::min(b.clipBegin, lane.resumeAt);
    b.clipEnd = std::max(b.clipEnd, lane.endAt);
    b.nextEnd = std::min(b.nextEnd, lane.endAt);
  }
}

// MIP: the largest whole density the window shows black, and the smallest it shows white
// (mipPixel is monotone in the density, so every sample up to the one shows black, and every
// sample from the other white).
struct MipBounds {
  float black = 0.f;
  float white = std::numeric_limits<float>::infinity();
};
MipBounds mipBounds(const MipWindow& window) {
  MipBounds bounds;
  int d = 0;
  for (; d < kDensityLevels && mipPixel(float(d), window).r <= 0.f; ++d) bounds.black = float(d);
  for (; d < kDensityLevels; ++d)
    if (mipPixel(float(d), window).r >= 1.f) return {bounds.black, float(d)};
  return bounds;
}

// MIP: the pixel of a ray whose column was never started (no tile could raise its maximum above
// mipBlack): black where it has samples in the domain and the clipping's interval, none where it
// has none (as a started lane's `shows` says).
glm::vec4 unstartedMipPixel(const Frame& f, int x, int y) {
  if (f.clipped && clippedSampleRange(f.view, f.params.clipping, f.view.rayOrigin(x, y)).empty())
    return glm::vec4(0.f);
  return mipPixel(f.mipBlack, f.params.mip);
}

// Column x's state, made in place (a column is started for every bundle that reaches it: a copy
// of the state was measurable).
template <class Sampler>
void startColumn(const Frame& f, const RowBundle& bundle, int x,
                 std::optional<BundleRay<Sampler>>& state) {
  BundleRay<Sampler>& b =
      state.emplace(RaySamples(f.volume, f.view, f.view.rayOrigin(x, bundle.firstRow)),
                    Sampler(f.voxels, f.rayStepQ, f.view.axis, densityReader<typename Sampler::Read>(f)),
                    bundle.lanes);
  for (int l = 0; l < bundle.lanes; ++l) {
    b.lanes[l].regions = RegionCursor(f.regionTables.regions, x, bundle.firstRow + l);
    b.lanes[l].mipMaximum = f.mipBlack;
  }
  if (f.clipped) clipLanes(f, bundle, x, b);
  // The rows of a bundle differ only along the rotation axis, inside the domain: one range.
  if (f.segments) b.domainEnd = sampleRange(f.view, f.view.rayOrigin(x, bundle.firstRow)).last + 1;
}

template <class Mode, class Sampler>
void writePixels(const Frame& f, const RowBundle& bundle, const RowScratch<Sampler>& scratch,
                 Image& image) {
  const RayTemplates& templates = f.templates;
  for (int r = 0; r < bundle.rows; ++r) {
    const int y = bundle.firstRow + r, l = std::min(r, bundle.lanes - 1);
    for (int x = 0; x < f.view.width; ++x) {
      if (!f.wanted(x, y)) continue;
      const auto& b = scratch.rays[x];
      if (!b)
        image.at(x, y) = Mode::mip && templates.columnBegin[x] != templates.columnBegin[x + 1]
                             ? unstartedMipPixel(f, x, y)
                             : glm::vec4(0.f);
      else
        image.at(x, y) = !Mode::mip          ? b->lanes[l].ray.pixel()
                         : b->lanes[l].shows ? mipPixel(b->lanes[l].mipMaximum, f.params.mip)
                                             : glm::vec4(0.f);
    }
  }
}

// Profiling: the samples of one rank's group visits, in the domain and, where the group is
// skipped for the whole row, skipped by groups (rays already terminated aside: ERT saved those).
template <class Sampler>
void countRank(const Frame& f, const RowBundle& bundle, std::size_t rank, RowScratch<Sampler>& scratch) {
  const RayTemplates& templates = f.templates;
  const bool skipped = f.skipGroups && !scratch.tiles.groupMask[templates.rankGroup[rank]];
  for (std::uint32_t v = templates.rankBegin[rank]; v < templates.rankBegin[rank + 1]; ++v) {
    const GroupVisit visit = templates.visits[v];
    const GroupRun& group = templates.groups[visit.groupRun];
    std::uint64_t samples = 0;
    for (std::uint32_t r = group.firstRun; r < group.endRun; ++r) samples += templates.runs[r].count;
    scratch.profile.domainSamples += samples * bundle.rows;
    const auto& state = scratch.rays[visit.column];
    if (skipped) {
      const int live = state ? state->live : bundle.lanes;
      scratch.profile.skippedByGroups += samples * live * raysPerLane(bundle);
    }
  }
}

// Renders one bundle of rows group by group in front-to-back order (RayTemplates::visits), each
// column keeping its state in between; returns false if cancelled part-way (checked every 4 groups).
template <class Mode, class Sampler>
bool renderBundle(const Frame& f, const RowBundle& bundle, RowScratch<Sampler>& scratch, Image& image,
                  std::uint64_t& samples) {
  if (bundle.outside) {
    if (!f.pixels) {
      std::fill_n(&image.at(0, bundle.firstRow), std::size_t(f.view.width) * bundle.rows,
                  glm::vec4(0.f));
      return true;
    }
    for (int y = bundle.firstRow; y < bundle.firstRow + bundle.rows; ++y)
      for (int x = 0; x < f.view.width; ++x)
        if (f.wanted(x, y)) image.at(x, y) = glm::vec4(0.f);
    return true;
  }
  if (cancelRequested(f.options)) return false;
  // Every row of the bundle reads the first row's slices (nearest, trilinear) or a subset of them
  // (mean: the same nearest voxel), so its classification holds for all.
  classifyRow(f, bundle.qa, scratch.tiles);
  markWantedColumns(f, bundle, scratch);
  auto& rays = scratch.rays;
  rays.resize(f.view.width);
  for (auto& ray : rays) ray.reset();
  const RayTemplates& templates = f.templates;
  for (std::size_t rank = 0; rank + 1 < templates.rankBegin.size(); ++rank) {
    if (cancelRequested(f.options)) return false;  // a relaxed load per group: free
    const std::int32_t group = templates.rankGroup[rank];
    if constexpr (Mode::profile) countRank(f, bundle, rank, scratch);
    if (!Mode::mip && f.skipGroups && !scratch.tiles.groupMask[group]) continue;
    // MIP: a group no denser than the window's black raises no ray's maximum; columns that only
    // cross such groups are never started (unstartedMipPixel).
    if (Mode::mip && f.skipGroups && float(scratch.tiles.groupMaxDensity[group]) <= f.mipBlack) continue;
    for (std::uint32_t v = templates.rankBegin[rank]; v < templates.rankBegin[rank + 1]; ++v) {
      const GroupVisit visit = templates.visits[v];
      auto& state = rays[visit.column];
      if (!state) {
        if (f.pixels && !scratch.columns[visit.column]) continue;
        startColumn(f, bundle, int(visit.column), state);
        if constexpr (Mode::profile) {
          state->profile = &scratch.profile;
          scratch.profile.rays += bundle.rows;
        }
      } else if (state->live == 0) {
        continue;
      }
      visitGroup<Mode>(f, bundle, scratch.tiles, templates.groups[visit.groupRun], *state, samples);
    }
  }
  writePixels<Mode>(f, bundle, scratch, image);
  return true;
}

// What the workers count: the samples in tiles not skipped, and (profiling) where they went.
struct WorkerCounts {
  std::uint64_t samples = 0;
  RayProfile profile;
};

// Renders bundles [first, end); returns false if cancelled.
template <class Mode, class Sampler>
bool renderRows(const Frame& f, const RowBundle* first, const RowBundle* end, Image& image,
                WorkerCounts& counts) {
  RowScratch<Sampler> scratch;
  bool finished = true;
  for (const RowBundle* bundle = first; bundle != end && finished; ++bundle) {
    finished = renderBundle<Mode>(f, *bundle, scratch, image, counts.samples);
    if (finished && f.options.rowsDone)
      f.options.rowsDone->fetch_add(bundle->rows, std::memory_order_relaxed);
  }
  counts.profile += scratch.profile;
  return finished;
}

using RowFunction = bool (*)(const Frame&, const RowBundle*, const RowBundle*, Image&, WorkerCounts&);

template <class Mode>
RowFunction rowFunctionFor(Filter filter) {
  using Read = std::conditional_t<Mode::labels, MaskedDensity, PlainDensity>;
  switch (filter) {
    case Filter::nearest: return renderRows<Mode, NearestRaySampler<Read>>;
    case Filter::mean: return renderRows<Mode, MeanRaySampler<Read>>;
    case Filter::trilinear: return renderRows<Mode, TrilinearRaySampler<Read>>;
  }
  return renderRows<Mode, NearestRaySampler<Read>>;
}

template <bool Mip, bool Regions>
RowFunction rowFunctionFor(Filter filter, bool labels) {
  return labels ? rowFunctionFor<Compiled<Mip, Regions, true>>(filter)
                : rowFunctionFor<Compiled<Mip, Regions, false>>(filter);
}

// Whether a frame is profiled: asked for, and plain DVR (the one mode that counts).
bool profiled(const RenderParams& params, bool regions, bool labels, const FastRenderOptions& options) {
  return options.profile && params.compositing == Compositing::dvr && !regions && !labels;
}

// The row renderer compiled for the frame's filter, compositing, regions and labels.
RowFunction rowFunctionFor(const RenderParams& params, bool regions, bool labels, bool profile) {
  const bool mip = params.compositing == Compositing::mip;
  const Filter filter = params.sampling.filter;
  if (profile) return rowFunctionFor<Compiled<false, false, false, true>>(filter);
  if (regions)
    return mip ? rowFunctionFor<true, true>(filter, labels)
               : rowFunctionFor<false, true>(filter, labels);
  return mip ? rowFunctionFor<true, false>(filter, labels)
             : rowFunctionFor<false, false>(filter, labels);
}

// The frame's image, its pixels unset: every pixel is written by its row, so neither recycled
// nor fresh memory needs clearing (and fresh pages are touched by the rows, which can be cancelled).
Image frameImage(const ViewGeometry& view, Image* recycle) {
  Image image;
  if (recycle) {
    image = std::move(*recycle);
    *recycle = Image{};
  }
  image.width = view.width;
  image.height = view.height;
  const std::size_t pixels = std::size_t(view.width) * view.height;
  // Growing would copy the old pixels into the new memory (touching its pages): they are not needed.
  if (image.pixels.capacity() < pixels) image.pixels = Pixels();
  image.pixels.resize(pixels);
  return image;
}

}  // namespace

bool blocksServe(const BlockedVolume& blocked, const RegionTables& tables, const RenderParams& params) {
  // MIP: every density a background block can give (below the threshold, or the dummy's 0) shows
  // black, as the true one does.
  if (params.compositing == Compositing::mip)
    return float(blocked.backgroundDensity - 1) <= mipBounds(params.mip).black;
  if (params.sampling.preintegrated) return false;
  // Background blocks hold label 0 only, which never has a TF of its own (core/label_tables.h).
  for (const TfTable* table : {tables.focus, tables.context, tables.outside})
    if (table && table->anyVisible(0, blocked.backgroundDensity - 1)) return false;
  return true;
}

Image renderFast(const Volume& volume, const TileClassification& classification, const TfTable& table,
                 const RenderParams& params, const FastRenderOptions& options, FastRenderStats* stats) {
  return renderFast(volume, classification, singleTable(table), params, options, stats);
}

Image renderFast(const Volume& volume, const TileClassification& classification,
                 const RegionTables& tables, const RenderParams& params,
                 const FastRenderOptions& options, FastRenderStats* stats) {
  if (classification.axis() != params.axis)
    throw std::logic_error("renderFast: the tile classification is of another rotation axis");
  if (!classification.classifies(tables))
    throw std::logic_error("renderFast: the tile classification was made for other TFs");
  if (params.compositing == Compositing::mip && !classification.hasMaxima())
    throw std::logic_error("renderFast: MIP needs a tile classification with maxima");
  const auto start = std::chrono::steady_clock::now();
  const SliceTiles& tiles = classification.tiles();
  const bool labels = tables.labelsActive();
  if (options.blocks && !blocksServe(*options.blocks, tables, params))
    throw std::logic_error("renderFast: the blocked volume cannot render this frame exactly");
  Frame f{volume,
          options.blocks ? VoxelGrid(volume, *options.blocks) : VoxelGrid(volume),
          tiles,
          classification.visibleMasks(params.sampling.filter),
          params,
          options,
          tables,
          classification.maxDensity(params.sampling.filter),
          labels ? *tables.labels : LabelTables(),
          makeViewGeometry(volume, params),
          frameTables(tables, params.sampling.osd),
          {}};
  // Visible where any region's or label's TF is: a cell hidden from all is hidden from its samples.
  std::vector<const TfTable*> anyTables = {f.tfOf(Region::focus), f.tfOf(Region::context),
                                           f.tfOf(Region::outside)};
  for (int label = 0; label < kLabelCount; ++label) anyTables.push_back(f.labels.ownTf(label));
  const TfTable anyRegion = visibilityUnion(anyTables);
  f.anyRegionTf = &anyRegion;
  f.skipGroups = options.skipEmpty && options.skipGroups;
  f.skipTiles = options.skipEmpty && options.skipTiles;
  f.shareRows = options.shareRows;
  f.batchSamples = options.batchSamples;
  f.ownTfs = f.labels.ownsAny();
  if (f.ownTfs && f.tables.hasOutside) buildLaneTables(f);
  f.clipped = params.clipping.any();
  if (params.compositing == Compositing::mip) {
    const MipBounds bounds = mipBounds(params.mip);
    f.mipBlack = bounds.black;
    f.mipWhite = bounds.white;
  }
  f.pixels = options.pixels;
  if (f.pixels && f.pixels->size() != std::size_t(f.view.width) * f.view.height)
    throw std::logic_error("renderFast: the pixel mask is not of the view's size");
  // Cell skipping pays only with several samples per cell: at osd 1 (about one sample per cell)
  // the test and leap cost more than the interpolation they save (`angioray bench` times both).
  f.skipCells = options.skipEmpty && options.skipCells && params.sampling.osd < 0.75;
  f.rayStepQ = RaySamples(volume, f.view, glm::dvec3(0.0)).stepQ;
  std::optional<PreintegratedTables> segments;
  if (params.sampling.preintegrated && params.compositing == Compositing::dvr) {
    segments = preintegratedTables(tables, params.sampling.osd);
    f.segments = &*segments;
  }
  f.templates = buildRayTemplates(volume, f.view, tiles, options.cancel);
  const double templateMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  Image image = frameImage(f.view, options.recycle);  // unset pixels: no time spent on a cancel
  if (cancelRequested(options)) {
    if (stats) *stats = {0, templateMs, true, false, {}};
    return image;
  }

  const bool profile = profiled(params, tables.regions != nullptr, labels, options);
  const RowFunction renderRowsFn = rowFunctionFor(params, tables.regions != nullptr, labels, profile);
  std::mutex countsMutex;
  WorkerCounts total;
  std::atomic<bool> cancelled{false};
  const std::vector<RowBundle> bundles = rowBundles(f);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, bundles.size()),
      [&](const tbb::blocked_range<std::size_t>& range) {
        WorkerCounts local;
        if (!renderRowsFn(f, bundles.data() + range.begin(), bundles.data() + range.end(), image, local))
          cancelled = true;
        const std::lock_guard<std::mutex> lock(countsMutex);
        total.samples += local.samples;
        total.profile += local.profile;
      });
  if (stats) *stats = {total.samples, templateMs, cancelled.load(), profile, total.profile};
  return image;
}

}  // namespace angio
