// Pre-integrated classification (core/preintegration.h): the segment table against closed forms
// of the emission-absorption integral, and the fast raycaster's pre-integrated image against the
// reference raycaster's (an independent walk: every sample, its front read at the sample before),
// with empty-space skipping, labels and clipping, where the skipping must stay exact.
#include <cmath>

#include <gtest/gtest.h>

#include "core/fast_raycaster.h"
#include "core/label_tables.h"
#include "core/preintegration.h"
#include "core/reference_raycaster.h"
#include "io/tf_file.h"
#include "phantom/phantom.h"
#include "tests/support/image_difference.h"

namespace angio {
namespace {

using test_support::maxChannelDifference;

TransferFunction tfOf(std::vector<ControlPoint> points) {
  TransferFunction tf;
  tf.points = std::move(points);
  return tf;
}

// A segment that stays within one table entry is the post-classified sample, to the bit: a
// constant medium renders as without pre-integration.
TEST(Preintegration, ASegmentWithinOneEntryIsThePostClassifiedSample) {
  const TfTable table = buildTable(loadPresetOrFile("cta-vessels-bone"));
  for (double osd : {0.3, 1.0, 3.0}) {
    const PreintegratedTable segments(table, osd);
    const SampleTable post = correctedTable(table, osd);
    for (int d = 0; d < kDensityLevels; d += 7) {
      EXPECT_EQ(segments.segment(float(d), float(d)), post[d]) << d;
      EXPECT_EQ(segments.segment(float(d) - 0.4f, float(d) + 0.3f), post[d]) << d;
    }
  }
}

// Opacity rising linearly over the densities, colour constant: the extinction integral along a
// linear path has a closed form, tau = -ln(1 - a(s)), int -ln(u) ds over u = 1 - a(s). The table
// takes tau constant over each entry (the midpoint rule), which for this smooth ramp is within 1e-5.
TEST(Preintegration, ALinearOpacityRampIntegratesInClosedForm) {
  const double lo = 1000, hi = 3000, top = 0.6;  // densities; opacity 0 at lo .. top at hi
  const glm::vec3 color(0.2f, 0.5f, 0.9f);
  const TfTable table = buildTable(tfOf({{huOfDensity(lo), color, 0}, {huOfDensity(hi), color, top}}));
  const double slope = top / (hi - lo);
  // Antiderivative of -ln(1 - a(s)) in s: with u = 1 - a, ds = -du / slope.
  auto primitive = [&](double s) {
    const double u = 1.0 - slope * (s - lo);
    return (u * std::log(u) - u) / slope;
  };
  for (double osd : {0.5, 1.0, 2.5})
    for (auto [front, back] : {std::pair{1100.0, 1500.0}, {2900.0, 1200.0}, {1800.0, 1810.0}}) {
      const PreintegratedTable segments(table, osd);
      const double meanTau = (primitive(back) - primitive(front)) / (back - front);
      const double alpha = 1.0 - std::exp(-osd * meanTau);
      const glm::vec4 rgba = segments.segment(float(front), float(back));
      EXPECT_NEAR(rgba.a, alpha, 1e-5) << front << " -> " << back << " osd " << osd;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgba[c], color[c], 1e-6);
    }
}

// Constant opacity, colour changing linearly along the segment by dc: the exact emission is
//   C = c0 alpha + g (1 - e^-x (1 + x)) / tau,  x = tau L,
// and the table's (self-attenuation neglected) differs from it by about dc alpha^2 / 12, within
// dc alpha^2 / 8 for alpha up to 0.5: second order in the segment's opacity.
TEST(Preintegration, AColourRampIsEmittedWithinTheStatedSecondOrderError) {
  const double a = 0.2, lo = 1000, hi = 3000;
  const TfTable table =
      buildTable(tfOf({{huOfDensity(lo), {0, 0, 0}, a}, {huOfDensity(hi), {1, 1, 1}, a}}));
  for (double osd : {0.3, 1.0, 3.0}) {
    const PreintegratedTable segments(table, osd);
    const double front = 1200, back = 2600;
    const double tau = -std::log(1.0 - a), L = osd, x = tau * L;
    const double c0 = (front - lo) / (hi - lo), dc = (back - front) / (hi - lo), g = dc / L;
    const double alpha = 1.0 - std::exp(-x);
    const double exact = c0 * alpha + g * (1.0 - std::exp(-x) * (1.0 + x)) / tau;
    const glm::vec4 rgba = segments.segment(float(front), float(back));
    ASSERT_LE(alpha, 0.5);
    EXPECT_NEAR(rgba.a, alpha, 1e-6);
    EXPECT_NEAR(rgba.r * rgba.a, exact, dc * alpha * alpha / 8) << "osd " << osd;
    // Not the plain post-classified back sample: the segment's colour is its mean.
    EXPECT_NEAR(rgba.r, c0 + dc / 2, 1e-3);
  }
}

// A shell of 4 visible densities between two samples that both miss it: post-classification sees
// nothing, the segment its share of the way (4 of 20 density units) through it.
TEST(Preintegration, AThinShellBetweenTwoSamplesStillColoursTheSegment) {
  const glm::vec3 red(1, 0, 0);
  const TfTable table = buildTable(tfOf({{huOfDensity(1998.5), red, 0},
                                         {huOfDensity(1998.6), red, 0.5},
                                         {huOfDensity(2002.4), red, 0.5},
                                         {huOfDensity(2002.5), red, 0}}));
  const double osd = 2.0;
  const PreintegratedTable segments(table, osd);
  const SampleTable post = correctedTable(table, osd);
  EXPECT_EQ(post[1990].a, 0.f);
  EXPECT_EQ(post[2010].a, 0.f);
  const double covered = 4.0 / 20.0;  // entries 1999..2002 of the 20 units from 1990 to 2010
  const double alpha = 1.0 - std::pow(0.5, osd * covered);
  for (auto [front, back] : {std::pair{1990.f, 2010.f}, {2010.f, 1990.f}}) {
    const glm::vec4 rgba = segments.segment(front, back);
    EXPECT_NEAR(rgba.a, alpha, 1e-6);
    EXPECT_NEAR(rgba.r, 1.f, 1e-6);
    EXPECT_NEAR(rgba.g, 0.f, 1e-6);
  }
  // And a segment that ends before the shell sees nothing: exactly zero, as skipping assumes.
  EXPECT_EQ(segments.segment(1900.f, 1998.f), glm::vec4(0.f));
}

// An opaque entry (opacity 1: infinite extinction) on the way makes the segment opaque, and the
// segments beyond it stay finite.
TEST(Preintegration, AnOpaqueEntryMakesTheSegmentOpaqueAndLeavesOthersFinite) {
  const TfTable table =
      buildTable(tfOf({{huOfDensity(0), {1, 1, 1}, 0}, {huOfDensity(2000), {1, 1, 1}, 1}}));
  const PreintegratedTable segments(table, 0.3);
  EXPECT_GT(segments.segment(1990.f, 2050.f).a, 0.9999f);
  const glm::vec4 beyond = segments.segment(3000.f, 3500.f);
  for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isfinite(beyond[c]));
  EXPECT_GT(beyond.a, 0.9999f);
}

struct Scene {
  Volume volume;
  TransferFunction tf;
};

Scene realisticPhantom() {
  return {generatePhantom({.dims = {48, 48, 112}, .seed = 3, .style = PhantomStyle::realistic}).volume,
          loadPresetOrFile("cta-vessels-bone")};
}

// Both raycasters pre-integrated, ERT off; the fast one must also have skipped samples.
void expectFastEqualsReference(const Volume& volume, const RegionTables& tables, RenderParams p,
                               const std::string& what) {
  p.sampling.preintegrated = true;
  p.sampling.ert = 1.0;
  const SliceTiles tiles = buildSliceTiles(volume, p.axis);
  const TileClassification visible(tiles, tables);
  const Image reference = renderReference(volume, tables, p);
  FastRenderStats skipped, all;
  const Image fast = renderFast(volume, visible, tables, p, {}, &skipped);
  EXPECT_LE(maxChannelDifference(fast, reference), 1.f / 255.f) << what;
  FastRenderOptions everything;
  everything.skipEmpty = false;
  renderFast(volume, visible, tables, p, everything, &all);
  EXPECT_LT(skipped.samples, all.samples) << what;
  // Pre-integration changes the image (else this compares nothing new).
  p.sampling.preintegrated = false;
  EXPECT_GT(maxChannelDifference(renderReference(volume, tables, p), reference), 2.f / 255.f) << what;
}

TEST(Preintegration, FastRaycasterEqualsReferenceForEveryFilterAndAxis) {
  const Scene scene = realisticPhantom();
  const TfTable table = buildTable(scene.tf);
  int n = 0;
  for (Axis axis : {Axis::k, Axis::i})
    for (Quality quality : {Quality::fast, Quality::medium, Quality::high})
      for (double osdScale : {1.0, 2.5}) {
        RenderParams p;
        p.axis = axis;
        p.angleDeg = 11.0 + 37.0 * n++;
        p.sampling = qualitySampling(quality);
        p.sampling.osd *= osdScale;
        expectFastEqualsReference(
            scene.volume, singleTable(table), p,
            std::string(toString(axis)) + " " + toString(quality) + " osd x" + std::to_string(osdScale));
      }
}

// A TF that shows a band of densities (vessel lumen) and hides what lies above it (bone): hidden
// cells on both sides of the band, so a segment from one hidden cell into another can cross the
// visible band, and cell skipping (the high level's osd) must see that.
TEST(Preintegration, FastRaycasterEqualsReferenceWithABandTf) {
  const Scene scene = realisticPhantom();
  const glm::vec3 red(0.9f, 0.2f, 0.1f);
  const TfTable table = buildTable(tfOf({{-1024, red, 0},
                                         {120, red, 0},
                                         {200, red, 0.5},
                                         {400, red, 0.5},
                                         {480, red, 0},
                                         {3071, red, 0}}));
  for (double osd : {0.3, 0.6}) {
    RenderParams p;
    p.angleDeg = 31;
    p.sampling = qualitySampling(Quality::high);
    p.sampling.osd = osd;
    expectFastEqualsReference(scene.volume, singleTable(table), p, "band osd " + std::to_string(osd));
  }
}

// Hidden labels and a label's own TF (the segment takes the back sample's TF), and a crop box whose
// first sample's front lies outside it: the fast raycaster reads that front as the reference does.
TEST(Preintegration, FastRaycasterEqualsReferenceWithLabelsAndClipping) {
  Scene scene = realisticPhantom();
  for (Voxel& v : scene.volume.voxels)
    if (huOfDensity(densityOf(v)) > 500) v = Voxel(densityOf(v) | (1 << 12));
  const TfTable table = buildTable(scene.tf);
  const LabelTables labels(
      {{1, "bone", LabelMode::tf, {{-1024, {1, 1, 1}, 0}, {3071, {1, 1, 1}, 0.3}}, {}}});
  const LabelTables hidden({{1, "bone", LabelMode::hidden, {}, {}}});
  const ViewGeometry whole = makeViewGeometry(scene.volume, RenderParams{});
  for (Quality quality : {Quality::medium, Quality::high}) {
    RenderParams p;
    p.angleDeg = 23;
    p.sampling = qualitySampling(quality);
    p.sampling.osd *= 2;
    expectFastEqualsReference(scene.volume, {nullptr, nullptr, nullptr, &table, &labels}, p,
                              std::string("own TF ") + toString(quality));
    expectFastEqualsReference(scene.volume, {nullptr, nullptr, nullptr, &table, &hidden}, p,
                              std::string("hidden ") + toString(quality));
    p.clipping.crop = CropBox{whole.extent * 0.2, whole.extent * 0.7};
    expectFastEqualsReference(scene.volume, singleTable(table), p,
                              std::string("cropped ") + toString(quality));
  }
}

}  // namespace
}  // namespace angio
