#include "render/frame_renderer.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <utility>

#include "core/adaptive_integration.h"
#include "core/adaptive_sampling.h"
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
    : volume_(volume), tiles_(std::move(ahead.tiles)), staleSlices_(std::move(ahead.staleSlices)) {
  if (tiles_ && !fits(*tiles_, volume_))
    throw std::invalid_argument("FrameRenderer: the slice tiles given are of another volume");
}

TilesAhead FrameRenderer::releaseTiles() {
  classification_.reset();
  classifiedScene_.reset();
  return {std::exchange(tiles_, nullptr), std::exchange(staleSlices_, {})};
}

void FrameRenderer::prepare(const std::shared_ptr<const PreparedScene>& scene, Axis axis,
                            Compositing compositing) {
  const bool mip = compositing == Compositing::mip;
  if (!tiles_ || tiles_->axis != axis) {
    classification_.reset();
    tiles_.reset();  // free the old tiles before building the new ones
    staleSlices_.clear();
    tiles_ = std::make_shared<SliceTiles>(buildSliceTiles(volume_, axis));
  }
  if (!staleSlices_.empty()) {
    classification_.reset();
    // Copied if someone else still reads them (tiles() handed them out).
    if (tiles_.use_count() > 1) tiles_ = std::make_shared<SliceTiles>(*tiles_);
    refreshSliceTiles(*tiles_, volume_, staleSlices_);
    staleSlices_.clear();
  }
  if (classification_ && classifiedScene_ == scene && (!mip || classification_->hasMaxima())) return;
  // The classification needs the region TFs only, not the regions: any non-null regions stand
  // for "VesselGlyph" here.
  std::optional<TileClassification> previous = std::move(classification_);
  classification_.emplace(*tiles_, scene->tables(scene->hasRegions() ? &regions_ : nullptr), mip,
                          previous ? &*previous : nullptr);
  classifiedScene_ = scene;
}

double FrameRenderer::structureMiB() const {
  if (!tiles_) return 0;
  const std::size_t classified = classification_ ? classification_->memoryBytes() : 0;
  return (tiles_->memoryBytes() + classified) / 1048576.0;
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
    prepare(scene, params.axis, params.compositing);
    FastRenderOptions options = techniques;
    options.cancel = control.cancel;
    options.recycle = control.recycle;
    options.rowsDone = control.rowsDone;
    image = renderFast(volume_, *classification_, tables, params, options, &s);
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
