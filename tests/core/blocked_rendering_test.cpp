// The fast raycaster reading the blocked volume (FastRenderOptions::blocks, core/voxel_grid.h)
// against reading the flat volume: the same bytes wherever blocksServe allows the blocks. The
// volume given with the blocks holds no voxels, so a read that still went to the flat voxels
// would crash (or fail under ASan) instead of passing.
#include <string>

#include <gtest/gtest.h>

#include "core/blocked_volume.h"
#include "core/fast_raycaster.h"
#include "core/label_tables.h"
#include "core/view_geometry.h"
#include "phantom/phantom.h"
#include "tests/support/image_difference.h"
#include "tests/support/labelled_volume.h"
#include "tests/support/varied_params.h"
#include "tests/support/varying_regions.h"

namespace angio {
namespace {

using test_support::showsSomething;

using test_support::variedParams;

// Sizes that are not multiples of 32, so blocks are partial at the far faces; air around the body
// fills whole blocks, which share the dummy.
struct Scene {
  Volume volume =
      generatePhantom({.dims = {77, 70, 100}, .seed = 7, .style = PhantomStyle::realistic}).volume;
  BlockedVolume blocked = buildBlockedVolume(volume);
  Volume geometry = geometryOnly(volume);

  static Volume geometryOnly(const Volume& volume) {
    Volume geometry = volume;
    geometry.voxels = {};
    return geometry;
  }
};

// Soft tissue faintly, vessels and bone: visible from -300 HU, transparent below the background
// threshold (-900 HU).
TfTable tissueTable() {
  return buildTable({"tissue, vessels and bone",
                     {{-1024, {0, 0, 0}, 0},
                      {-300, {0.8f, 0.5f, 0.4f}, 0},
                      {0, {0.8f, 0.4f, 0.3f}, 0.02f},
                      {200, {1, 0.2f, 0.2f}, 0.3f},
                      {600, {1, 1, 0.9f}, 0.8f}}});
}

TEST(BlockedRendering, SameImageAsTheFlatVolume) {
  const Scene scene;
  ASSERT_GT(scene.blocked.backgroundBlocks, 0);
  ASSERT_LT(scene.blocked.backgroundBlocks, scene.blocked.blockCount());
  const TfTable table = tissueTable();
  for (Axis axis : {Axis::k, Axis::i, Axis::j}) {
    const SliceTiles tiles = buildSliceTiles(scene.volume, axis);
    const TileClassification visible(tiles, singleTable(table), /*mip=*/false);
    for (Filter filter : {Filter::nearest, Filter::mean, Filter::trilinear})
      for (double osd : {1.0, 0.3})
        for (int variant = 0; variant < 3; ++variant) {
          const RenderParams p = variedParams(scene.volume, axis, filter, osd, variant);
          ASSERT_TRUE(blocksServe(scene.blocked, singleTable(table), p));
          const Image flat = renderFast(scene.volume, visible, table, p);
          ASSERT_TRUE(showsSomething(flat));
          FastRenderOptions fromBlocks;
          fromBlocks.blocks = &scene.blocked;
          FastRenderOptions fromBlocksOneByOne = fromBlocks;
          fromBlocksOneByOne.batchSamples = false;
          const auto where = [&] {
            return std::string(toString(axis)) + " filter " + std::to_string(int(filter)) + " osd " +
                   std::to_string(osd) + " variant " + std::to_string(variant);
          };
          EXPECT_TRUE(renderFast(scene.geometry, visible, table, p, fromBlocks).pixels == flat.pixels)
              << where();
          EXPECT_TRUE(renderFast(scene.geometry, visible, table, p, fromBlocksOneByOne).pixels ==
                      flat.pixels)
              << where() << ", one by one";
        }
  }
}

// Hidden labels read as density 0 (in the sample batches too, where no label has its own TF), own
// TFs pick by the nearest voxel's label; both read the label bits, which the blocks keep.
// VesselGlyph regions use two more TFs.
TEST(BlockedRendering, LabelsAndRegionsGiveTheFlatVolumesImage) {
  Scene scene;
  // Label 1 on dense voxels, label 2 on soft tissue.
  test_support::labelVoxels(scene.volume, [](int, int, int, double hu) {
    return hu > 500 ? 1 : hu > 20 && hu < 80 ? 2 : 0;
  });
  scene.blocked = buildBlockedVolume(scene.volume);
  const TfTable table = tissueTable();
  const LabelTables labels({{1, "bone", LabelMode::hidden, {}, {1, 1, 1}},
                            {2,
                             "tissue",
                             LabelMode::tf,
                             {{-1024, {0, 1, 0}, 0}, {-200, {0, 1, 0}, 0.1}, {3071, {0, 1, 0}, 0.1}},
                             {0, 1, 0}}});
  const LabelTables hiddenOnly({{1, "bone", LabelMode::hidden, {}, {1, 1, 1}}});  // batched
  const TfTable focus =
      buildTable({"focus", {{-1024, {0, 0, 0}, 0}, {50, {1, 0, 0}, 0}, {100, {1, 0, 0}, 0.6}}});
  for (Filter filter : {Filter::mean, Filter::trilinear}) {
    RenderParams p = variedParams(scene.volume, Axis::k, filter, 0.3, 0);
    const ViewGeometry view = makeViewGeometry(scene.volume, p);
    const RayRegions regions = test_support::varyingRegions(view, 3.f, 20, 4.f, 40.f);
    for (const RegionTables& tables : {RegionTables{nullptr, nullptr, nullptr, &table, &labels},
                                       RegionTables{nullptr, nullptr, nullptr, &table, &hiddenOnly},
                                       RegionTables{&regions, &focus, &table, nullptr, &labels}}) {
      const SliceTiles tiles = buildSliceTiles(scene.volume, Axis::k);
      const TileClassification visible(tiles, tables);
      ASSERT_TRUE(blocksServe(scene.blocked, tables, p));
      const Image flat = renderFast(scene.volume, visible, tables, p);
      ASSERT_TRUE(showsSomething(flat));
      FastRenderOptions fromBlocks;
      fromBlocks.blocks = &scene.blocked;
      EXPECT_TRUE(renderFast(scene.geometry, visible, tables, p, fromBlocks).pixels == flat.pixels)
          << "filter " << int(filter) << (tables.regions ? ", regions" : "")
          << (tables.labels == &hiddenOnly ? ", hidden only" : "");
    }
  }
}

// MIP reads the dummy's density 0 where the true maximum lies below the background threshold; the
// window shows both as black when its lower end is at or above the threshold.
TEST(BlockedRendering, MipThroughDummyBlocksWhereTheWindowBlackensBackground) {
  const Scene scene;
  const TfTable table = tissueTable();
  const SliceTiles tiles = buildSliceTiles(scene.volume, Axis::k);
  const TileClassification visible(tiles, singleTable(table), /*mip=*/true);
  RenderParams p = variedParams(scene.volume, Axis::k, Filter::trilinear, 0.3, 1);
  p.compositing = Compositing::mip;
  p.mip = {.window = 1200, .level = 300};  // black at -300 HU and below
  ASSERT_TRUE(blocksServe(scene.blocked, singleTable(table), p));
  for (Filter filter : {Filter::nearest, Filter::trilinear}) {
    p.sampling.filter = filter;
    FastRenderOptions fromBlocks;
    fromBlocks.blocks = &scene.blocked;
    const Image flat = renderFast(scene.volume, visible, table, p);
    EXPECT_TRUE(renderFast(scene.geometry, visible, table, p, fromBlocks).pixels == flat.pixels)
        << "filter " << int(filter);
  }
  // A window showing air (-1000 HU above black) would show the dummy's -1024 HU instead.
  p.mip = {.window = 800, .level = -700};
  EXPECT_FALSE(blocksServe(scene.blocked, singleTable(table), p));
}

TEST(BlockedRendering, RefusedWhereTheDummyWouldShow) {
  const Scene scene;
  const TfTable table = tissueTable();
  const TfTable air = buildTable({"air", {{-1024, {1, 1, 1}, 0.1}, {-950, {1, 1, 1}, 0}}});
  RenderParams p = variedParams(scene.volume, Axis::k, Filter::trilinear, 0.3, 0);
  EXPECT_TRUE(blocksServe(scene.blocked, singleTable(table), p));
  EXPECT_FALSE(blocksServe(scene.blocked, singleTable(air), p));
  // VesselGlyph's focus and context TFs count as well.
  EXPECT_FALSE(blocksServe(scene.blocked, RegionTables{nullptr, &air, &table, &table}, p));
  EXPECT_FALSE(blocksServe(scene.blocked, RegionTables{nullptr, &table, &air, &table}, p));
  p.sampling.preintegrated = true;
  EXPECT_FALSE(blocksServe(scene.blocked, singleTable(table), p));

  const SliceTiles tiles = buildSliceTiles(scene.volume, Axis::k);
  const TileClassification visible(tiles, singleTable(air));
  p.sampling.preintegrated = false;
  FastRenderOptions fromBlocks;
  fromBlocks.blocks = &scene.blocked;
  EXPECT_THROW(renderFast(scene.geometry, visible, air, p, fromBlocks), std::logic_error);
}

}  // namespace
}  // namespace angio
