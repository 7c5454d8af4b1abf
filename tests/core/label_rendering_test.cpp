// Per-label rendering (rendering model, "Labels"): a hidden label renders as if its voxels had been
// cut out of the scan (set to -1024 HU), a label's own TF classifies samples whose nearest voxel
// carries it, and the fast raycaster (with its tile classification) gives the reference's image
// with labels for every filter, MIP, axis and VesselGlyph regions.
#include <cmath>

#include <gtest/gtest.h>

#include "core/fast_raycaster.h"
#include "core/label_tables.h"
#include "core/reference_raycaster.h"
#include "core/view_geometry.h"
#include "phantom/phantom.h"
#include "tests/support/image_difference.h"
#include "tests/support/labelled_volume.h"
#include "tests/support/varying_regions.h"

namespace angio {
namespace {

using test_support::maxChannelDifference;

float brightest(const Image& image) {
  float most = 0.f;
  for (const glm::vec4& p : image.pixels) most = std::max({most, p.r, p.g, p.b});
  return most;
}

TransferFunction vesselsAndBone() {
  TransferFunction tf;
  tf.points = {{-1024, {0, 0, 0}, 0},
               {150, {0.8f, 0.1f, 0.1f}, 0},
               {300, {1, 0.4f, 0.3f}, 0.5},
               {900, {1, 1, 0.9f}, 0.9},
               {3071, {1, 1, 1}, 0.9}};
  return tf;
}

LabelStyle hidden(int label) { return {label, "cut", LabelMode::hidden, {}, {1, 1, 1}}; }

LabelStyle ownTf(int label, glm::vec3 color, double opacity) {
  return {label,
          "own",
          LabelMode::tf,
          {{-1024, color, 0}, {-200, color, opacity}, {3071, color, opacity}},
          color};
}

// The phantom with label 1 on its dense voxels (bone cortex and plaques, > 600 HU) and label 3 on
// a box through the pelvis and the arteries, so labels cut through bone, vessels and air.
Volume labelledPhantom() {
  Volume volume =
      generatePhantom({.dims = {48, 48, 112}, .seed = 1, .style = PhantomStyle::simple}).volume;
  test_support::labelVoxels(volume, [](int i, int, int k, double hu) {
    return hu > 600 ? 1 : i > 10 && i < 30 && k > 60 && k < 90 ? 3 : 0;
  });
  return volume;
}

RenderParams paramsFor(Axis axis, double angle, Quality quality, Compositing compositing) {
  RenderParams p;
  p.axis = axis;
  p.angleDeg = angle;
  p.sampling = qualitySampling(quality);
  p.sampling.ert = 1.0;
  p.compositing = compositing;
  return p;
}

TEST(LabelRendering, AHiddenLabelRendersAsIfCutOutOfTheScan) {
  const Volume labelled = labelledPhantom();
  Volume cut = labelled;  // the same scan with label 1 set to -1024 HU and unlabelled
  for (Voxel& v : cut.voxels)
    if (labelOf(v) == 1) v = 0;
    else if (labelOf(v) == 3) v = Voxel(densityOf(v));
  const TfTable table = buildTable(vesselsAndBone());
  const LabelTables labels({hidden(1)});
  for (Filter filter : {Filter::nearest, Filter::trilinear, Filter::mean})
    for (Compositing compositing : {Compositing::dvr, Compositing::mip}) {
      RenderParams p = paramsFor(Axis::k, 30, Quality::medium, compositing);
      p.sampling.filter = filter;
      const Image withLabels =
          renderReference(labelled, {nullptr, nullptr, nullptr, &table, &labels}, p);
      const Image cutOut = renderReference(cut, table, p);
      // The same voxel reads and the same operations: the same bits.
      EXPECT_EQ(maxChannelDifference(withLabels, cutOut), 0.f) << toString(filter);
      EXPECT_GT(brightest(cutOut), 0.2f);
      EXPECT_GT(maxChannelDifference(withLabels, renderReference(labelled, table, p)), 0.1f)
          << "hiding the dense voxels changes the image";
    }
}

TEST(LabelRendering, AnOwnTfColorsTheLabelsVoxels) {
  // A 9^3 box of 0 HU labelled 3 in a 17^3 air volume; main TF shows nothing below 200 HU, the
  // label's TF makes everything above -200 HU green. Unshaded nearest DVR through the centre:
  // the box's 9 samples at opacity 0.1 each.
  Volume volume = makeVolume({17, 17, 17}, {1, 1, 1});
  for (int k = 4; k <= 12; ++k)
    for (int j = 4; j <= 12; ++j)
      for (int i = 4; i <= 12; ++i) volume.voxels[volume.indexOf(i, j, k)] = encodeVoxel(0, 3);
  TransferFunction main;
  main.points = {{-1024, {1, 0, 0}, 0}, {200, {1, 0, 0}, 0}, {3071, {1, 0, 0}, 1}};
  const TfTable table = buildTable(main);
  const LabelTables labels({ownTf(3, {0, 1, 0}, 0.1)});
  RenderParams p = paramsFor(Axis::k, 0, Quality::medium, Compositing::dvr);
  p.shading.enabled = false;
  const ViewGeometry view = makeViewGeometry(volume, p);
  const Image image = renderReference(volume, {nullptr, nullptr, nullptr, &table, &labels}, p);
  const glm::vec4 centre = image.at(view.width / 2, view.height / 2);
  EXPECT_NEAR(centre.a, 1 - std::pow(0.9, 9), 1e-5);
  EXPECT_NEAR(centre.g, centre.a, 1e-5);
  EXPECT_EQ(centre.r, 0.f);
  EXPECT_EQ(renderReference(volume, table, p).at(view.width / 2, view.height / 2).a, 0.f);
  const SliceTiles tiles = buildSliceTiles(volume, Axis::k);
  const RegionTables tables{nullptr, nullptr, nullptr, &table, &labels};
  EXPECT_EQ(
      maxChannelDifference(renderFast(volume, TileClassification(tiles, tables), tables, p), image),
      0.f);
}

TEST(LabelRendering, AHiddenLabelLeavesNoTileVisible) {
  // Dense "bone" filling the middle of the volume, labelled 1: visible under the TF until hidden.
  Volume volume = makeVolume({64, 64, 16}, {1, 1, 1});
  for (int k = 0; k < 16; ++k)
    for (int j = 16; j < 48; ++j)
      for (int i = 16; i < 48; ++i) volume.voxels[volume.indexOf(i, j, k)] = encodeVoxel(1000, 1);
  const TfTable table = buildTable(vesselsAndBone());
  const SliceTiles tiles = buildSliceTiles(volume, Axis::k);
  const LabelTables shown, cut({hidden(1)});
  auto visibleTiles = [&](const LabelTables& labels) {
    const TileClassification c(tiles, RegionTables{nullptr, nullptr, nullptr, &table, &labels});
    return c.visibleTileCount(Filter::trilinear) + c.visibleTileCount(Filter::mean);
  };
  EXPECT_GT(visibleTiles(shown), 0);
  EXPECT_EQ(visibleTiles(cut), 0);
  const TileClassification c(tiles, RegionTables{nullptr, nullptr, nullptr, &table, &cut}, true);
  for (std::uint16_t d : c.maxDensity(Filter::trilinear)) EXPECT_EQ(d, 0);
  // MIP refuses a classification made without the maxima rather than skip by wrong ones.
  RenderParams mip;
  mip.compositing = Compositing::mip;
  const RegionTables tables{nullptr, nullptr, nullptr, &table, &cut};
  EXPECT_THROW(renderFast(volume, TileClassification(tiles, tables), tables, mip), std::logic_error);
  EXPECT_NO_THROW(renderFast(volume, TileClassification(tiles, tables, true), tables, mip));
}

// The fast raycaster against the reference with labels hidden, with own TFs, and both, over
// every filter, MIP and the three axes.
TEST(LabelRendering, FastMatchesReferenceWithLabels) {
  const Volume volume = labelledPhantom();
  const TfTable table = buildTable(vesselsAndBone());
  const std::vector<LabelTables> labelSets = {LabelTables({hidden(1)}),
                                              LabelTables({ownTf(3, {0.2f, 0.9f, 0.3f}, 0.05)}),
                                              LabelTables({ownTf(1, {0.9f, 0.9f, 1}, 0.02), hidden(3)})};
  int n = 0;
  for (Axis axis : {Axis::i, Axis::j, Axis::k}) {
    const SliceTiles tiles = buildSliceTiles(volume, axis);
    for (const LabelTables& labels : labelSets)
      for (Quality quality : {Quality::fast, Quality::medium, Quality::high})
        for (Compositing compositing : {Compositing::dvr, Compositing::mip}) {
          const RenderParams p = paramsFor(axis, 12.5 + 37.0 * n++, quality, compositing);
          const RegionTables tables{nullptr, nullptr, nullptr, &table, &labels};
          const Image reference = renderReference(volume, tables, p);
          const TileClassification classification(tiles, tables, compositing == Compositing::mip);
          const Image fast = renderFast(volume, classification, tables, p);
          EXPECT_LE(maxChannelDifference(fast, reference), 1.f / 255.f)
              << "axis " << toString(axis) << " " << toString(quality) << " mip "
              << (compositing == Compositing::mip) << " angle " << p.angleDeg;
          EXPECT_GT(brightest(reference), 0.2f);
        }
  }
}

TEST(LabelRendering, FastMatchesReferenceWithLabelsInVesselGlyphRegions) {
  const Volume volume = labelledPhantom();
  const TfTable focus = buildTable(vesselsAndBone());
  TransferFunction faint = vesselsAndBone();
  for (ControlPoint& point : faint.points) point.opacity *= 0.1;
  const TfTable context = buildTable(faint);
  const LabelTables labels({hidden(1), ownTf(3, {0.2f, 0.9f, 0.3f}, 0.05)});
  for (Quality quality : {Quality::medium, Quality::high}) {
    const RenderParams p = paramsFor(Axis::k, 20, quality, Compositing::dvr);
    const ViewGeometry view = makeViewGeometry(volume, p);
    const RayRegions regions = test_support::varyingRegions(view, 3.f, 20, 4.f, 40.f);
    const RegionTables tables{&regions, &focus, &context, nullptr, &labels};
    const SliceTiles tiles = buildSliceTiles(volume, Axis::k);
    const Image reference = renderReference(volume, tables, p);
    const Image fast = renderFast(volume, TileClassification(tiles, tables), tables, p);
    EXPECT_LE(maxChannelDifference(fast, reference), 1.f / 255.f) << toString(quality);
    EXPECT_GT(brightest(reference), 0.2f);
  }
}

TEST(LabelRendering, LabelTablesTakeTheFirstStyleOfALabelAndIgnoreLabelZero) {
  const LabelTables labels({hidden(2), ownTf(2, {0, 1, 0}, 0.5), hidden(0), ownTf(5, {1, 0, 0}, 0.2)});
  EXPECT_TRUE(labels.hidden(2));
  EXPECT_EQ(labels.ownTf(2), nullptr);
  EXPECT_FALSE(labels.hidden(0));
  EXPECT_NE(labels.ownTf(5), nullptr);
  EXPECT_EQ(labels.density()(encodeVoxel(500, 2)), 0);
  EXPECT_EQ(labels.density()(encodeVoxel(500, 5)), densityOfHu(500));
  EXPECT_FALSE(LabelTables().active());
}

}  // namespace
}  // namespace angio
