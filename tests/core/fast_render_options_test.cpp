// FastRenderOptions that must not change the image: recycled frame memory and row progress; and
// the skipping switches the bench turns off one at a time.
#include <atomic>
#include <string>

#include <tbb/global_control.h>

#include <gtest/gtest.h>

#include "core/fast_raycaster.h"
#include "core/label_tables.h"
#include "core/ray_templates.h"
#include "core/view_geometry.h"
#include "phantom/phantom.h"
#include "tests/support/image_difference.h"
#include "tests/support/labelled_volume.h"
#include "tests/support/varied_params.h"
#include "tests/support/varying_regions.h"

namespace angio {
namespace {

using test_support::showsSomething;

struct Scene {
  Volume volume =
      generatePhantom({.dims = {48, 48, 96}, .seed = 3, .style = PhantomStyle::simple}).volume;
  TfTable table =
      buildTable({"bone and vessels",
                  {{-1024, {0, 0, 0}, 0}, {150, {1, 0.3f, 0.2f}, 0}, {400, {1, 1, 0.9f}, 0.5}}});
  SliceTiles tiles = buildSliceTiles(volume, Axis::k);
  TileClassification visible{tiles, singleTable(table), /*mip=*/true};  // DVR and MIP

  Image render(Quality quality, double angle, const FastRenderOptions& options = {}) const {
    RenderParams p;
    p.angleDeg = angle;
    p.sampling = qualitySampling(quality);
    return renderFast(volume, visible, table, p, options);
  }
};

TEST(FastRenderOptions, RecycledMemoryOfAnotherSizeGivesTheSameImage) {
  const Scene scene;
  for (Quality quality : {Quality::fast, Quality::medium, Quality::high}) {
    const Image fresh = scene.render(quality, 40);
    ASSERT_TRUE(showsSomething(fresh));
    // A frame of another level and angle, so every pixel must be written again.
    Image previous = scene.render(quality == Quality::high ? Quality::fast : Quality::high, 75);
    FastRenderOptions options;
    options.recycle = &previous;
    const Image recycled = scene.render(quality, 40, options);
    EXPECT_TRUE(previous.pixels.empty());
    ASSERT_EQ(recycled.width, fresh.width);
    ASSERT_EQ(recycled.height, fresh.height);
    EXPECT_TRUE(recycled.pixels == fresh.pixels) << toString(quality);
  }
}

// A cancel that comes before the rows (while the templates are built) ends the frame without
// ordering the templates or clearing pixels: the frame keeps the recycled memory, unset.
TEST(FastRenderOptions, AFrameCancelledBeforeItsRowsKeepsTheRecycledMemoryAndRendersNothing) {
  const Scene scene;
  Image previous = scene.render(Quality::high, 75);  // larger than a medium frame
  const glm::vec4* memory = previous.pixels.data();
  const std::atomic<bool> cancel{true};
  FastRenderOptions options;
  options.cancel = &cancel;
  options.recycle = &previous;
  FastRenderStats stats;
  RenderParams p;
  p.sampling = qualitySampling(Quality::medium);
  const Image image = renderFast(scene.volume, scene.visible, scene.table, p, options, &stats);
  EXPECT_TRUE(stats.cancelled);
  EXPECT_EQ(stats.samples, 0u);
  EXPECT_EQ(image.pixels.data(), memory);
  EXPECT_EQ(image.pixels.size(), std::size_t(image.width) * image.height);

  const ViewGeometry view = makeViewGeometry(scene.volume, p);
  const RayTemplates templates = buildRayTemplates(scene.volume, view, scene.tiles, &cancel);
  EXPECT_TRUE(templates.columnBegin.empty());  // not even the columns gathered
  EXPECT_FALSE(buildRayTemplates(scene.volume, view, scene.tiles).visits.empty());
}

TEST(FastRenderOptions, EveryRowIsCountedOnceWhenDone) {
  const Scene scene;
  std::atomic<int> rows{0};
  FastRenderOptions options;
  options.rowsDone = &rows;
  const Image image = scene.render(Quality::medium, 10, options);
  EXPECT_EQ(rows.load(), image.height);
}

TEST(FastRenderOptions, EachSkippingLevelAloneKeepsTheImage) {
  const Scene scene;
  for (Quality quality : {Quality::medium, Quality::high}) {
    const Image all = scene.render(quality, 130);
    ASSERT_TRUE(showsSomething(all));
    for (int off = 0; off < 3; ++off) {
      FastRenderOptions options;
      options.skipGroups = off != 0;
      options.skipTiles = off != 1;
      options.skipCells = off != 2;
      EXPECT_TRUE(scene.render(quality, 130, options).pixels == all.pixels)
          << toString(quality) << " without skipping level " << off;
    }
  }
}

// Row bundles (rows reading the same voxels share one pass) against every row on its own: the
// same bits, for the filters that bundle (trilinear: per-row fractions; nearest: copied rows),
// DVR and MIP, about two axes (k has the shared-plane interpolation, i the general one).
TEST(FastRenderOptions, RowBundlesKeepTheImage) {
  const Scene scene;
  for (Axis axis : {Axis::k, Axis::i}) {
    const SliceTiles tiles = buildSliceTiles(scene.volume, axis);
    const TileClassification visible(tiles, singleTable(scene.table), /*mip=*/true);  // DVR and MIP
    for (Quality quality : {Quality::medium, Quality::high})
      for (Compositing mode : {Compositing::dvr, Compositing::mip}) {
        RenderParams p;
        p.axis = axis;
        p.angleDeg = 57;
        p.sampling = qualitySampling(quality);
        p.compositing = mode;
        FastRenderOptions separate;
        separate.shareRows = false;
        const Image bundled = renderFast(scene.volume, visible, scene.table, p);
        ASSERT_TRUE(showsSomething(bundled));
        EXPECT_TRUE(renderFast(scene.volume, visible, scene.table, p, separate).pixels == bundled.pixels)
            << toString(axis) << " " << toString(quality)
            << (mode == Compositing::mip ? " mip" : " dvr");
      }
  }
}

TfTable softTissueAndVessels() {
  return buildTable({"soft tissue and vessels",
                     {{-1024, {0, 0, 0}, 0},
                      {0, {0.8f, 0.4f, 0.3f}, 0.02f},
                      {200, {1, 0.2f, 0.2f}, 0.3f},
                      {600, {1, 1, 0.9f}, 0.8f}}});
}

// One frame batched against one by one, bit for bit; the frame must show something. Returns the
// batched image.
Image expectBatchedEqualsOneByOne(const Volume& volume, const TileClassification& visible,
                                  const RegionTables& tables, const RenderParams& p,
                                  const std::string& what) {
  const Image batched = renderFast(volume, visible, tables, p);
  EXPECT_TRUE(showsSomething(batched)) << what;
  FastRenderOptions oneByOne;
  oneByOne.batchSamples = false;
  EXPECT_TRUE(renderFast(volume, visible, tables, p, oneByOne).pixels == batched.pixels) << what;
  return batched;
}

// Batched against one by one, bit for bit, for both filters that batch (nearest does not), DVR and
// MIP, osd 1 and 0.3, shaded or not, and clipped (test_support::variedParams). With `unlabelled`,
// the same frame without the tables' labels must differ, so the labels are in effect.
void expectBatchesKeepTheImage(const Volume& volume, const RegionTables& tables,
                               std::initializer_list<Axis> axes, const TfTable* unlabelled = nullptr) {
  for (Axis axis : axes) {
    const SliceTiles tiles = buildSliceTiles(volume, axis);
    const TileClassification visible(tiles, tables, /*mip=*/true);  // DVR and MIP
    for (Compositing compositing : {Compositing::dvr, Compositing::mip})
      for (Filter filter : {Filter::mean, Filter::trilinear})
        for (double osd : {1.0, 0.3})
          for (int variant = 0; variant < 3; ++variant) {
            RenderParams p = test_support::variedParams(volume, axis, filter, osd, variant);
            p.compositing = compositing;
            const Image batched = expectBatchedEqualsOneByOne(
                volume, visible, tables, p,
                std::string(toString(axis)) + (compositing == Compositing::mip ? " mip" : " dvr") +
                    " filter " + std::to_string(int(filter)) + " osd " + std::to_string(osd) +
                    " variant " + std::to_string(variant));
            if (unlabelled) {
              const TileClassification plain(tiles, singleTable(*unlabelled), /*mip=*/true);
              EXPECT_FALSE(renderFast(volume, plain, *unlabelled, p).pixels == batched.pixels);
            }
          }
  }
}

// Eight samples reconstructed and classified at once (core/sample_batch.h) against one by one,
// about every axis. The crop box and tilted plane start the rows of a bundle at different samples;
// the volume's odd voxel count and its faces exercise the batches' fallback to the scalar path.
TEST(FastRenderOptions, SampleBatchesKeepTheImage) {
  const Volume volume =
      generatePhantom({.dims = {37, 41, 59}, .seed = 5, .style = PhantomStyle::realistic}).volume;
  ASSERT_EQ(volume.voxels.size() % 2, 1u);
  const TfTable table = softTissueAndVessels();
  expectBatchesKeepTheImage(volume, singleTable(table), {Axis::k, Axis::i, Axis::j});
}

// The same with hidden labels (bone removal): the lanes read a hidden label's voxels as density 0,
// as MaskedDensity does one by one. Label 1 on dense voxels (bone), label 3 on a box through the
// body, label 2 elsewhere and shown.
TEST(FastRenderOptions, SampleBatchesKeepTheImageWithHiddenLabels) {
  Volume volume =
      generatePhantom({.dims = {37, 41, 59}, .seed = 5, .style = PhantomStyle::realistic}).volume;
  test_support::labelVoxels(volume, [](int i, int, int k, double hu) {
    return hu > 500 ? 1 : (i > 12 && i < 25 && k > 20) ? 3 : 2;
  });
  const TfTable table = softTissueAndVessels();
  const LabelTables hidden(
      {{1, "bone", LabelMode::hidden, {}, {1, 1, 1}}, {3, "box", LabelMode::hidden, {}, {1, 1, 1}}});
  expectBatchesKeepTheImage(volume, RegionTables{nullptr, nullptr, nullptr, &table, &hidden},
                            {Axis::k, Axis::i}, &table);
}

// The same with labels that have TFs of their own (each lane picks its sample's table by the label
// of its nearest voxel or corner, as one by one): label 1 (200..500 HU) and label 3 (a box through
// the body) each with its own TF, label 2 (above 500 HU) hidden, so that MIP changes too; the rest
// unlabelled. Rotation about k and i, so the rows of a bundle see different nearest corners.
TEST(FastRenderOptions, SampleBatchesKeepTheImageWithLabelsOfTheirOwnTf) {
  Volume volume =
      generatePhantom({.dims = {37, 41, 59}, .seed = 5, .style = PhantomStyle::realistic}).volume;
  test_support::labelVoxels(volume, [](int i, int, int k, double hu) {
    if (hu > 500) return 2;
    if (hu > 200) return 1;
    return (i > 12 && i < 25 && k > 20) ? 3 : 0;
  });
  const TfTable table = softTissueAndVessels();
  const LabelTables labels(
      {{1, "bone", LabelMode::tf, {{200, {1, 1, 1}, 0.f}, {900, {1, 1, 1}, 0.5f}}, {1, 1, 1}},
       {2, "hidden", LabelMode::hidden, {}, {1, 1, 1}},
       {3, "box", LabelMode::tf, {{-200, {0, 0.5f, 1}, 0.05f}, {300, {0, 1, 1}, 0.4f}}, {0, 1, 1}}});
  expectBatchesKeepTheImage(volume, RegionTables{nullptr, nullptr, nullptr, &table, &labels},
                            {Axis::k, Axis::i}, &table);
}

// The same with VesselGlyph regions (DVR): each lane classifies a batch with its region's table,
// none where its region is not rendered, and a batch in which a lane's region changes goes one by
// one. Focus and context at depths that vary from ray to ray (test_support::varyingRegions), the
// outside shown or not rendered, both filters (the mean batches only single-row bundles here).
TEST(FastRenderOptions, SampleBatchesKeepTheImageWithVesselGlyphRegions) {
  const Volume volume =
      generatePhantom({.dims = {37, 41, 59}, .seed = 5, .style = PhantomStyle::realistic}).volume;
  const TfTable table = softTissueAndVessels();
  const TfTable focus =
      buildTable({"focus", {{-1024, {0, 0, 0}, 0}, {50, {1, 0, 0}, 0}, {150, {1, 0.2f, 0}, 0.6f}}});
  const TfTable* notRendered = nullptr;
  for (Axis axis : {Axis::k, Axis::i}) {
    const SliceTiles tiles = buildSliceTiles(volume, axis);
    for (Filter filter : {Filter::mean, Filter::trilinear})
      for (double osd : {1.0, 0.3})
        for (int variant = 0; variant < 3; ++variant)
          for (const TfTable* outside : {&table, notRendered}) {
            const RenderParams p = test_support::variedParams(volume, axis, filter, osd, variant);
            const RayRegions regions =
                test_support::varyingRegions(makeViewGeometry(volume, p), 2.f, 12, 3.f, 30.f);
            const RegionTables tables{&regions, &focus, &table, outside};
            const TileClassification visible(tiles, tables);
            expectBatchedEqualsOneByOne(volume, visible, tables, p,
                                        std::string(toString(axis)) + " filter " +
                                            std::to_string(int(filter)) + " osd " + std::to_string(osd) +
                                            " variant " + std::to_string(variant) +
                                            (outside ? "" : ", outside not rendered"));
          }
  }
}

// Rows and bundles are split among threads as oneTBB likes; each pixel must not care.
TEST(FastRenderOptions, SameBytesWhateverTheThreadCount) {
  const Scene scene;
  for (Quality quality : {Quality::fast, Quality::medium, Quality::high}) {
    Image oneThread;
    {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
      oneThread = scene.render(quality, 200);
    }
    ASSERT_TRUE(showsSomething(oneThread));
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 4);
    EXPECT_TRUE(scene.render(quality, 200).pixels == oneThread.pixels) << toString(quality);
  }
}

}  // namespace
}  // namespace angio
