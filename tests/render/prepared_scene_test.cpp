// Prepared scenes and the frame renderer: one recipe gives one image however it is reached (a
// fresh scene, a scene that borrowed the previous one's tubes, a frame renderer reused across
// scenes and axes), and bad recipes are refused when prepared.
#include <atomic>
#include <memory>

#include <gtest/gtest.h>

#include "io/input_error.h"
#include "io/tf_file.h"
#include "phantom/phantom.h"
#include "render/frame_renderer.h"
#include "render/prepared_scene.h"
#include "core/slice_tiles.h"
#include "tests/support/phantom_in_volume_frame.h"

namespace angio {
namespace {

using test_support::PhantomInVolumeFrame;

const PhantomInVolumeFrame& testData() {
  static const PhantomInVolumeFrame data = test_support::phantomInVolumeFrame({64, 64, 128});
  return data;
}

RenderRecipe vesselGlyphRecipe() {
  RenderRecipe recipe;
  recipe.tf = loadPresetOrFile("cta-vessels-bone");
  recipe.params.angleDeg = 40;
  recipe.params.sampling = qualitySampling(Quality::medium);
  recipe.vesselGlyph = VesselGlyphRecipe{"phantom",
                                         {},
                                         loadPresetOrFile("cta-vessels"),
                                         loadPresetOrFile("soft-tissue-context"),
                                         std::nullopt};
  return recipe;
}

Image fresh(const RenderRecipe& recipe) {
  return renderRecipe(testData().volume, testData().centerlines, recipe);
}

bool hasVisiblePixel(const Image& image) {
  for (const glm::vec4& p : image.pixels)
    if (p.a > 0.f) return true;
  return false;
}

TEST(PreparedScene, AScenePreparedAfterAnotherRendersAsAFreshOne) {
  const PhantomInVolumeFrame& data = testData();
  const RenderRecipe first = vesselGlyphRecipe();
  const auto before = PreparedScene::prepare(data.volume, data.centerlines, first);
  FrameRenderer frames(data.volume);
  EXPECT_EQ(frames.render(before).pixels, fresh(first).pixels);

  RenderRecipe tfEdit = first;  // the tubes can be lent
  tfEdit.vesselGlyph->focusTf.modulators.opacityScale = 0.5;
  RenderRecipe shapeEdit = first;  // they cannot
  shapeEdit.vesselGlyph->settings.focus.value = 4;
  shapeEdit.vesselGlyph->settings.cleft = true;
  for (const RenderRecipe& edited : {tfEdit, shapeEdit}) {
    const auto after = PreparedScene::prepare(data.volume, data.centerlines, edited, before.get());
    const Image image = frames.render(after);
    EXPECT_TRUE(hasVisiblePixel(image));
    EXPECT_EQ(image.pixels, fresh(edited).pixels);
    EXPECT_NE(image.pixels, fresh(first).pixels);
  }
}

TEST(FrameRenderer, OneRendererAcrossScenesAndAxesGivesEachRecipesImage) {
  const PhantomInVolumeFrame& data = testData();
  FrameRenderer frames(data.volume);
  RenderRecipe plain;
  plain.tf = loadPresetOrFile("cta-vessels-bone");
  plain.params.sampling = qualitySampling(Quality::fast);
  RenderRecipe mip = plain;
  mip.params.compositing = Compositing::mip;
  const RenderRecipe glyph = vesselGlyphRecipe();
  RenderRecipe reference = glyph;
  reference.raycaster = Raycaster::reference;
  for (const Axis axis : {Axis::k, Axis::i, Axis::k}) {
    for (RenderRecipe recipe : {plain, mip, glyph, reference}) {
      recipe.params.axis = axis;
      const auto scene = PreparedScene::prepare(data.volume, data.centerlines, recipe);
      const Image image = frames.render(scene);
      EXPECT_TRUE(hasVisiblePixel(image)) << toString(axis);
      EXPECT_EQ(image.pixels, fresh(recipe).pixels) << toString(axis);
    }
  }
}

// Tiles built ahead (as a load builds them) are the ones the renderer uses for their axis, give
// the image it gives with its own, and give way to new ones for another axis.
TEST(FrameRenderer, TilesBuiltAheadAreUsedForTheirAxisOnly) {
  const PhantomInVolumeFrame& data = testData();
  const auto ahead = std::make_shared<SliceTiles>(buildSliceTiles(data.volume, Axis::k));
  FrameRenderer frames(data.volume, TilesAhead{ahead, {}});
  EXPECT_EQ(frames.tiles(), ahead);
  RenderRecipe recipe = vesselGlyphRecipe();
  const auto scene = PreparedScene::prepare(data.volume, data.centerlines, recipe);
  EXPECT_EQ(frames.render(scene).pixels, fresh(recipe).pixels);
  EXPECT_EQ(frames.tiles(), ahead);

  recipe.params.axis = Axis::i;
  const auto aboutI = PreparedScene::prepare(data.volume, data.centerlines, recipe);
  EXPECT_EQ(frames.render(aboutI).pixels, fresh(recipe).pixels);
  ASSERT_NE(frames.tiles(), nullptr);
  EXPECT_EQ(frames.tiles()->axis, Axis::i);
}

// A rotation about the long axis goes back and forth between the tiles about i and about j: the
// renderer keeps both. A cancelled build of new tiles gives no image and goes on with the next
// render about that axis.
TEST(FrameRenderer, KeepsTheTilesOfTheAxisBeforeAndACancelledBuildGoesOnLater) {
  const PhantomInVolumeFrame& data = testData();
  RenderRecipe recipe;
  recipe.params.axis = Axis::k;
  const auto aboutK = PreparedScene::prepare(data.volume, data.centerlines, recipe);
  FrameRenderer frames(data.volume);
  const Image firstK = frames.render(aboutK);
  const auto tilesK = frames.tiles();
  ASSERT_NE(tilesK, nullptr);

  recipe.params.axis = Axis::i;
  const auto aboutI = PreparedScene::prepare(data.volume, data.centerlines, recipe);
  const std::atomic<bool> cancelled{true};
  FastRenderStats stats;
  const Image none = frames.render(aboutI, RenderControl{&cancelled}, &stats);
  EXPECT_TRUE(stats.cancelled);
  EXPECT_TRUE(none.pixels.empty());
  EXPECT_EQ(frames.tiles(), nullptr);  // not built to the end
  EXPECT_FALSE(frames.prepare(aboutI, Axis::i, Compositing::dvr, &cancelled));
  EXPECT_EQ(frames.render(aboutI).pixels, fresh(recipe).pixels);
  const auto tilesI = frames.tiles();
  ASSERT_NE(tilesI, nullptr);
  EXPECT_EQ(tilesI->axis, Axis::i);

  EXPECT_EQ(frames.render(aboutK).pixels, firstK.pixels);
  EXPECT_EQ(frames.tiles(), tilesK);  // the same tiles again, not built anew
  EXPECT_EQ(frames.render(aboutI).pixels, fresh(recipe).pixels);
  EXPECT_EQ(frames.tiles(), tilesI);
  // A label change's next renderer gets the current axis's complete tiles.
  EXPECT_EQ(frames.releaseTiles().tiles, tilesI);
}

// The progressive renderer stops a build of new tiles when a request about another axis comes:
// the build goes on later where it stopped, and a label change meanwhile gets the complete tiles
// of the axis before rather than the half-built ones.
TEST(FrameRenderer, ABuildStoppedHalfwayForAnotherAxisGoesOnWhereItStopped) {
  const PhantomInVolumeFrame& data = testData();
  RenderRecipe recipe;
  recipe.params.axis = Axis::i;
  const auto aboutI = PreparedScene::prepare(data.volume, data.centerlines, recipe);
  recipe.params.axis = Axis::k;
  const auto aboutK = PreparedScene::prepare(data.volume, data.centerlines, recipe);
  std::atomic<bool> cancel{false};
  std::vector<double> built;  // the fractions the builds report
  const auto stopAfterOneGroup = [&](double fraction) {
    built.push_back(fraction);
    cancel = true;
  };
  const auto record = [&](double fraction) { built.push_back(fraction); };

  FrameRenderer frames(data.volume);
  const Image firstI = frames.render(aboutI);
  const auto tilesI = frames.tiles();
  ASSERT_NE(tilesI, nullptr);
  // About k the 128 slices of 64^2 voxels are summarised in two groups of 64 (core/slice_tiles).
  EXPECT_FALSE(frames.prepare(aboutK, Axis::k, Compositing::dvr, &cancel, stopAfterOneGroup));
  ASSERT_EQ(built, std::vector<double>{0.5});
  EXPECT_EQ(frames.tiles(), nullptr);
  EXPECT_EQ(frames.render(aboutI).pixels, firstI.pixels);
  EXPECT_EQ(frames.tiles(), tilesI);  // kept, not built again
  built.clear();
  ASSERT_TRUE(frames.prepare(aboutK, Axis::k, Compositing::dvr, nullptr, record));
  EXPECT_EQ(built, std::vector<double>{1.0});  // only the second group was left to build
  EXPECT_EQ(frames.render(aboutK).pixels, fresh(recipe).pixels);

  FrameRenderer interrupted(data.volume);
  interrupted.render(aboutI);
  const auto completeI = interrupted.tiles();
  cancel = false;
  EXPECT_FALSE(interrupted.prepare(aboutK, Axis::k, Compositing::dvr, &cancel, stopAfterOneGroup));
  const TilesAhead released = interrupted.releaseTiles();
  EXPECT_EQ(released.tiles, completeI);
  EXPECT_TRUE(released.staleSlices.empty());
}

TEST(FrameRenderer, TilesOfAnotherVolumeAreRefused) {
  const Volume other = generatePhantom(PhantomOptions{{32, 32, 40}}).volume;
  const auto tiles = std::make_shared<SliceTiles>(buildSliceTiles(other, Axis::k));
  EXPECT_THROW(FrameRenderer(testData().volume, TilesAhead{tiles, {}}), std::invalid_argument);
}

// After a label change the next renderer takes the tiles of the one before with the slices the
// change touched marked stale: its image is the one of tiles built from scratch. The change gives
// back voxels of a hidden label, which stale tiles would skip as hidden.
TEST(FrameRenderer, TilesKeptOverALabelChangeRefreshTheSlicesItTouched) {
  const PhantomInVolumeFrame& data = testData();
  Volume volume = data.volume;
  std::vector<std::size_t> box;
  for (int k = 40; k < 90; ++k)
    for (int j = 0; j < volume.dims.y; ++j)
      for (int i = 0; i < volume.dims.x; ++i) box.push_back(volume.indexOf(i, j, k));
  for (const std::size_t n : box) volume.voxels[n] = Voxel(volume.voxels[n] | (1 << 12));
  RenderRecipe recipe;
  recipe.tf = loadPresetOrFile("cta-vessels-bone");
  recipe.tf.labels = {LabelStyle{1, "removed", LabelMode::hidden}};
  recipe.params.angleDeg = 30;
  const Image withLabel = renderRecipe(volume, data.centerlines, recipe);

  FrameRenderer before(volume);
  before.render(PreparedScene::prepare(volume, data.centerlines, recipe));
  TilesAhead tiles = before.releaseTiles();
  ASSERT_NE(tiles.tiles, nullptr);
  EXPECT_EQ(before.tiles(), nullptr);
  for (const std::size_t n : box) volume.voxels[n] = Voxel(densityOf(volume.voxels[n]));
  tiles.markStale(slicesHolding(volume, Axis::k, box));
  ASSERT_EQ(tiles.staleSlices.size(), 50u);

  const SliceTiles* kept = tiles.tiles.get();
  FrameRenderer after(volume, std::move(tiles));
  const Image image = after.render(PreparedScene::prepare(volume, data.centerlines, recipe));
  EXPECT_EQ(after.tiles().get(), kept);  // refreshed in place, not built again
  EXPECT_NE(image.pixels, withLabel.pixels);
  EXPECT_EQ(image.pixels, renderRecipe(volume, data.centerlines, recipe).pixels);
}

TEST(TilesAhead, StaleSlicesMergeAscendingWithoutRepeats) {
  TilesAhead tiles;
  tiles.markStale({2, 5, 9});
  tiles.markStale({1, 5, 12});
  EXPECT_EQ(tiles.staleSlices, (std::vector<int>{1, 2, 5, 9, 12}));
}

// The fast raycaster gives the reference's image (core/fast_raycaster.h), with regions too.
TEST(FrameRenderer, TheRecipesRaycasterChoiceGivesTheSameImage) {
  RenderRecipe recipe = vesselGlyphRecipe();
  recipe.params.sampling.ert = 1;
  const Image fast = fresh(recipe);
  recipe.raycaster = Raycaster::reference;
  const Image reference = fresh(recipe);
  ASSERT_EQ(fast.pixels.size(), reference.pixels.size());
  float worst = 0;
  for (std::size_t n = 0; n < fast.pixels.size(); ++n)
    for (int c = 0; c < 4; ++c)
      worst = std::max(worst, std::abs(fast.pixels[n][c] - reference.pixels[n][c]));
  EXPECT_LE(worst, 1.f / 255.f);
}

TEST(PreparedScene, AHybridOfAPathThatIsNotThereIsRefusedWhenPrepared) {
  RenderRecipe recipe = vesselGlyphRecipe();
  recipe.hybrid = HybridCprRecipe{"99", 0, std::nullopt};
  EXPECT_THROW(PreparedScene::prepare(testData().volume, testData().centerlines, recipe), InputError);
  recipe.hybrid->path = "0";
  const auto scene = PreparedScene::prepare(testData().volume, testData().centerlines, recipe);
  RenderRecipe withoutHybrid = recipe;
  withoutHybrid.hybrid.reset();
  EXPECT_NE(FrameRenderer(testData().volume).render(scene).pixels, fresh(withoutHybrid).pixels);
}

}  // namespace
}  // namespace angio
