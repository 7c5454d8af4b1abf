#include "render/frame_renderer.h"

#include <algorithm>
#include <iterator>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "core/adaptive_integration.h"
#include "core/adaptive_sampling.h"
#include "core/image_refinement.h"
#include "core/reference_raycaster.h"

namespace angio {

namespace {

bool fits(const SliceTiles& tiles, const Volume& volume) {
  return tiles.slices == volume.dims[int(tiles.axis)] &&
         tiles.tilesB == tilesAlong(volume.dims[tiles.axisB]) &&
         tiles.tilesC == tilesAlong(volume.dims[tiles.axisC]);
}

}  // namespace

void TilesAhead::markStale(const std::vector<int>& slices) {
  std::vector<int> merged;
  std::set_union(staleSlices.begin(), staleSlices.end(), slices.begin(), slices.end(),
                 std::back_inserter(merged));
  staleSlices = std::move(merged);
}

FrameRenderer::FrameRenderer(const Volume& volume, TilesAhead ahead)
    : volume_(volume), current_{std::move(ahead.tiles), {}}, staleSlices_(std::move(ahead.staleSlices)) {
  if (current_.tiles && !fits(*current_.tiles, volume_))
    throw std::invalid_argument("FrameRenderer: the slice tiles given are of another volume");
}

TilesAhead FrameRenderer::releaseTiles() {
  classification_.reset();
  classifiedScene_.reset();
  AxisTiles current = std::exchange(current_, {});
  AxisTiles spare = std::exchange(spare_, {});
  std::vector<int> stale = std::exchange(staleSlices_, {});
  if (current.complete()) return {std::move(current.tiles), std::move(stale)};
  if (spare.complete()) return {std::move(spare.tiles), {}};
  return {};
}

bool FrameRenderer::volumeHasLabels() const {
  if (current_.complete() && staleSlices_.empty()) return current_.tiles->labelled;
  if (spare_.complete()) return spare_.tiles->labelled;
  return angio::volumeHasLabels(volume_);
}

// The tiles of `axis` become the current ones: the spare ones if they are of that axis, else new
// ones to build; the current ones become the spare (unless stale: a label change's tiles are
// refreshed for their own axis only).
void FrameRenderer::switchAxis(Axis axis) {
  classification_.reset();
  if (!staleSlices_.empty()) {
    current_ = {};
    staleSlices_.clear();
  }
  if (spare_.tiles && spare_.tiles->axis == axis) {
    std::swap(current_, spare_);
    return;
  }
  const bool labelled = volumeHasLabels();
  spare_ = std::exchange(current_, {});  // the tiles before the spare ones are freed first
  current_.tiles = std::make_shared<SliceTiles>(unsummarisedSliceTiles(volume_, axis, labelled));
  current_.unbuilt.resize(std::size_t(current_.tiles->slices));
  std::iota(current_.unbuilt.begin(), current_.unbuilt.end(), 0);
}

bool FrameRenderer::prepare(const std::shared_ptr<const PreparedScene>& scene, Axis axis,
                            Compositing compositing, const std::atomic<bool>* cancel,
                            const std::function<void(double)>& tilesBuilt) {
  const bool mip = compositing == Compositing::mip;
  if (!current_.tiles || current_.tiles->axis != axis) switchAxis(axis);
  if (!summariseSliceTiles(*current_.tiles, volume_, current_.unbuilt, cancel, tilesBuilt)) return false;
  if (!staleSlices_.empty()) {
    classification_.reset();
    // Copied if someone else still reads them (tiles() handed them out).
    std::shared_ptr<SliceTiles>& tiles = current_.tiles;
    if (tiles.use_count() > 1) tiles = std::make_shared<SliceTiles>(*tiles);
    refreshSliceTiles(*tiles, volume_, staleSlices_);
    staleSlices_.clear();
  }
  if (classification_ && classifiedScene_ == scene && (!mip || classification_->hasMaxima()))
    return true;
  // The classification needs the region TFs only, not the regions: any non-null regions stand
  // for "VesselGlyph" here.
  std::optional<TileClassification> previous = std::move(classification_);
  classification_.emplace(*current_.tiles, scene->tables(scene->hasRegions() ? &regions_ : nullptr), mip,
                          previous ? &*previous : nullptr);
  classifiedScene_ = scene;
  return true;
}

double FrameRenderer::structureMiB() const {
  std::size_t bytes = classification_ ? classification_->memoryBytes() : 0;
  for (const AxisTiles* axisTiles : {&current_, &spare_})
    if (axisTiles->tiles) bytes += axisTiles->tiles->memoryBytes();
  return bytes / 1048576.0;
}

Image FrameRenderer::render(const std::shared_ptr<const PreparedScene>& scene,
                            const RenderParams& params, const RenderControl& control,
                            FastRenderStats* stats) {
  const ViewGeometry view = makeViewGeometry(volume_, params);
  if (scene->hasRegions()) scene->buildRegions(view, regions_);
  const RegionTables tables = scene->tables(scene->hasRegions() ? &regions_ : nullptr);
  FastRenderStats local;
  FastRenderStats& s = stats ? *stats : local;
  Image image;
  // MIP takes the maximum of the samples, adaptive integration or not (as pre-integration).
  if (params.sampling.adaptive && params.compositing == Compositing::dvr) {
    AdaptiveIntegrationStats adaptive;
    image = renderAdaptive(volume_, tables, params, &adaptive, control.cancel, control.rowsDone);
    s = {};
    s.samples = adaptive.nodes;
    s.cancelled = adaptive.cancelled;
  } else if (params.sampling.adaptiveSampling && params.compositing == Compositing::dvr) {
    AdaptiveSamplingStats adaptive;
    image = renderAdaptiveSampling(volume_, tables,
                                   oracleFor(scene, tables, params.sampling.adaptiveSampling->tolerance),
                                   params, &adaptive, control.cancel, control.rowsDone);
    s = {};
    s.samples = adaptive.samples;
    s.cancelled = adaptive.cancelled;
  } else if (scene->recipe().raycaster == Raycaster::reference) {
    s = {};
    image = renderReference(volume_, tables, params, control.progress);
  } else {
    if (!prepare(scene, params.axis, params.compositing, control.cancel)) {
      s = {};
      s.cancelled = true;
      return image;
    }
    FastRenderOptions options = techniques;
    options.cancel = control.cancel;
    options.recycle = control.recycle;
    options.rowsDone = control.rowsDone;
    image = refinement
                ? renderRefined(volume_, *classification_, tables, params, *refinement, options, &s)
                : renderFast(volume_, *classification_, tables, params, options, &s);
  }
  if (!s.cancelled) scene->finish(view, regions_, image);
  return image;
}

const SamplingOracle& FrameRenderer::oracleFor(const std::shared_ptr<const PreparedScene>& scene,
                                               const RegionTables& tables, double tolerance) {
  OracleKey key{scene, tolerance};
  if (!(key == oracleKey_)) {
    oracle_ = makeSamplingOracle(volume_, tables, tolerance);
    oracleKey_ = std::move(key);
  }
  return oracle_;
}

Image renderRecipe(const Volume& volume, const Centerlines& centerlines, const RenderRecipe& recipe,
                   const RenderControl& control, PreparedScene::Warn warn, FastRenderStats* stats) {
  FrameRenderer renderer(volume);
  return renderer.render(PreparedScene::prepare(volume, centerlines, recipe, nullptr, std::move(warn)),
                         control, stats);
}

}  // namespace angio
