#pragma once
// The one path from a prepared scene and a view to pixels, for the window's progressive renderer,
// `angioray render`, exports, rotation series and bench alike. A FrameRenderer keeps what
// successive renders of one volume share: the slice tiles of the current rotation axis and of the
// one before (a rotation about the patient's long axis goes back and forth between i and j), the
// tile classification of the current scene (made again for another scene), the buffers of the
// rays' regions. One per thread of use; each render runs in parallel inside (oneTBB, in whatever
// arena the caller runs it).
#include <atomic>
#include <functional>
#include <memory>
#include <optional>

#include "core/fast_raycaster.h"
#include "core/sampling_oracle.h"
#include "core/image.h"
#include "core/image_refinement.h"
#include "core/region_intervals.h"
#include "core/render_params.h"
#include "core/slice_tiles.h"
#include "core/tile_classification.h"
#include "core/volume.h"
#include "render/prepared_scene.h"

namespace angio {

// How a render may be watched and stopped.
struct RenderControl {
  const std::atomic<bool>* cancel = nullptr;  // set: the fast raycaster stops within a row
  std::atomic<int>* rowsDone = nullptr;       // incremented per finished image row (fast raycaster)
  Image* recycle = nullptr;                   // an earlier image whose memory the new one takes
  std::function<void(double)> progress;       // the reference raycaster's progress in [0, 1]
};

// Slice tiles for some axis made before a frame needs them: by a load, for the axis the view
// starts with, or kept from the renderer before a label change, which makes the slices it touched
// stale: they are summarised again (refreshSliceTiles) before the tiles' first use.
struct TilesAhead {
  std::shared_ptr<SliceTiles> tiles;
  std::vector<int> staleSlices;  // ascending

  // Adds `slices` (ascending) to the stale ones.
  void markStale(const std::vector<int>& slices);
};

class FrameRenderer {
 public:
  // `ahead`: the volume's slice tiles for some axis, so that the first frame need not build them
  // (a refresh of their stale slices is all it does); renders about another axis build their own.
  // Throws std::invalid_argument when they do not fit the volume.
  explicit FrameRenderer(const Volume& volume, TilesAhead ahead = {});

  // The image of `scene` seen with `params` (view, sampling, shading, compositing): the scene's
  // recipe's raycaster with its TFs and regions, then its finish step (the hybrid) unless the
  // render was cancelled. `scene` must be of this renderer's volume.
  Image render(const std::shared_ptr<const PreparedScene>& scene, const RenderParams& params,
               const RenderControl& control = {}, FastRenderStats* stats = nullptr);
  // ... with the recipe's own parameters.
  Image render(const std::shared_ptr<const PreparedScene>& scene, const RenderControl& control = {},
               FastRenderStats* stats = nullptr) {
    return render(scene, scene->recipe().params, control, stats);
  }

  // Builds the tiles of `axis` and classifies them for `scene` now rather than in the next
  // render (the progressive renderer does this before a request's first level).
  // MIP needs the tiles' maxima as the scene's labels read them (`compositing`).
  // A build of new tiles stops between groups of slices once `cancel` is set (false: not
  // prepared; a cancelled render returns no image); the next prepare for that axis goes on
  // where it stopped. `tilesBuilt` gets the fraction of the tiles' slices built, as it grows.
  bool prepare(const std::shared_ptr<const PreparedScene>& scene, Axis axis,
               Compositing compositing = Compositing::dvr, const std::atomic<bool>* cancel = nullptr,
               const std::function<void(double)>& tilesBuilt = {});

  // Memory of the slice tiles (packed ranges, core/slice_tiles.h; both axes kept) and their
  // classification, MiB.
  double structureMiB() const;
  // The slice tiles of the last prepared axis (or those given to the constructor); null: none yet
  // or not yet built to the end.
  std::shared_ptr<const SliceTiles> tiles() const {
    return current_.unbuilt.empty() ? current_.tiles : nullptr;
  }
  // Gives up the slice tiles of the last prepared axis (or else of the one before) with the
  // slices still stale in them; the renderer has none after.
  TilesAhead releaseTiles();

  // Which of the fast raycaster's techniques run (the bench switches them; the image is the same).
  // Its cancel, recycle and rowsDone come from each render's RenderControl.
  FastRenderOptions techniques;
  // The bench's image-plane refinement of the fast raycaster's frames (core/image_refinement.h), for
  // `bench --approximations` only: it did not pay (README), so no recipe or sidecar names it.
  std::optional<ImageRefinement> refinement;

 private:
  // Whether some voxel carries a label: known from complete tiles, else read from the volume.
  bool volumeHasLabels() const;
  void switchAxis(Axis axis);

  // The slice tiles of one axis, complete or not: a build stopped by a cancel goes on later.
  struct AxisTiles {
    std::shared_ptr<SliceTiles> tiles;
    std::vector<int> unbuilt;  // slices not summarised yet (ascending)
    bool complete() const { return tiles && unbuilt.empty(); }
  };

  const Volume& volume_;
  AxisTiles current_;             // of the last prepared axis
  std::vector<int> staleSlices_;  // of current_, to refresh before their first use
  AxisTiles spare_;               // of the axis before
  std::shared_ptr<const PreparedScene> classifiedScene_;
  std::optional<TileClassification> classification_;
  RayRegions regions_;  // the view's, buffers reused from render to render
  // Adaptive sampling's oracle (core/sampling_oracle.h).
  // Made again for another scene (TF, labels) or tolerance; shared by the levels.
  struct OracleKey {
    std::shared_ptr<const PreparedScene> scene;
    double tolerance = 0;
    friend bool operator==(const OracleKey&, const OracleKey&) = default;
  };
  const SamplingOracle& oracleFor(const std::shared_ptr<const PreparedScene>& scene,
                                  const RegionTables& tables, double tolerance);
  OracleKey oracleKey_;
  SamplingOracle oracle_;
};

// One image of a recipe, for callers with one view: prepare, then render.
Image renderRecipe(const Volume& volume, const Centerlines& centerlines, const RenderRecipe& recipe,
                   const RenderControl& control = {}, PreparedScene::Warn warn = {},
                   FastRenderStats* stats = nullptr);

}  // namespace angio
