// Adaptive sampling in three dimensions (seed 003, core/adaptive_sampling.h) against independent
// paths and analytic cases: without levels it is the reference raycaster's pre-integrated image; a
// volume whose density is linear (which B-spline subdivision and pre-integration reproduce exactly)
// renders the same with the longest skips; a thin shell that the skips would jump over is kept by
// the oracle; and the image does not depend on the thread count.
#include <cmath>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "core/adaptive_sampling.h"
#include "core/reference_raycaster.h"
#include "core/view_geometry.h"
#include "io/tf_file.h"
#include "phantom/phantom.h"
#include "tests/support/filled_volume.h"
#include "tests/support/image_difference.h"

namespace angio {
namespace {

using test_support::filledVolume;
using test_support::maxChannelDifference;

RenderParams adaptiveParams(Quality quality, int levels, int rayLevels, double tolerance = 0.02) {
  RenderParams p;
  p.sampling = qualitySampling(quality);
  p.sampling.adaptiveSampling = AdaptiveSampling{levels, rayLevels, tolerance};
  return p;
}

Image renderAdaptively(const Volume& volume, const TfTable& table, const RenderParams& p,
                       AdaptiveSamplingStats* stats = nullptr) {
  const RegionTables tables = singleTable(table);
  const double tolerance = p.sampling.adaptiveSampling ? p.sampling.adaptiveSampling->tolerance : 0.02;
  return renderAdaptiveSampling(volume, tables, makeSamplingOracle(volume, tables, tolerance), p, stats);
}

Image preintegratedReference(const Volume& volume, const TfTable& table, RenderParams p) {
  p.sampling.adaptiveSampling.reset();
  p.sampling.preintegrated = true;
  return renderReference(volume, table, p);
}

TEST(AdaptiveSampling, WithoutLevelsItIsThePreintegratedReferenceImage) {
  const Volume volume =
      generatePhantom({.dims = {40, 40, 90}, .seed = 5, .style = PhantomStyle::realistic}).volume;
  const TfTable table = buildTable(loadPresetOrFile("cta-vessels-bone"));
  int n = 0;
  for (Quality quality : {Quality::fast, Quality::medium, Quality::high})
    for (double ert : {0.98, 1.0}) {
      RenderParams p = adaptiveParams(quality, 0, 0);
      p.angleDeg = 13.0 + 41.0 * n++;
      p.sampling.ert = ert;
      const Image adaptive = renderAdaptively(volume, table, p);
      const Image reference = preintegratedReference(volume, table, p);
      EXPECT_LE(maxChannelDifference(adaptive, reference), 2e-6f) << toString(quality) << " ert " << ert;
    }
}

// Density linear in depth (j, the view direction at angle 0) and in the image's up axis (k):
// biquadratic B-spline subdivision reproduces it exactly, and pre-integration of a segment of any
// length integrates it exactly (white TF, opacity only). With no edge anywhere (an infinite
// tolerance) every ray waits 2^3 samples and 7 of 8 rays of a row are synthesised, yet the image is
// the exact one but for rounding - and for the rows within 12 of the volume's top and bottom,
// where coarse pixels outside the volume read its clamped, no longer linear, edge.
TEST(AdaptiveSampling, ALinearVolumeRendersExactlyWithTheLongestSkips) {
  Volume volume = filledVolume({24, 64, 72}, 0);
  for (int k = 0; k < volume.dims.z; ++k)
    for (int j = 0; j < volume.dims.y; ++j)
      for (int i = 0; i < volume.dims.x; ++i)
        volume.voxels[volume.indexOf(i, j, k)] = Voxel(1000 + 9 * j + 7 * k);
  TransferFunction tf;
  tf.points = {{huOfDensity(900), {1, 1, 1}, 0}, {huOfDensity(2200), {1, 1, 1}, 0.08}};
  const TfTable table = buildTable(tf);
  RenderParams p = adaptiveParams(Quality::medium, 3, 6, 1e9);
  p.sampling.filter = Filter::trilinear;
  p.sampling.ert = 1.0;
  p.shading.enabled = false;
  AdaptiveSamplingStats skipping, every;
  const Image adaptive = renderAdaptively(volume, table, p, &skipping);
  RenderParams exact = p;
  exact.sampling.adaptiveSampling = AdaptiveSampling{0, 0, 1e9};
  const Image reference = renderAdaptively(volume, table, exact, &every);
  EXPECT_LE(maxChannelDifference(reference, preintegratedReference(volume, table, p)), 2e-6f);
  const ViewGeometry view = makeViewGeometry(volume, p);
  float worst = 0.f, visible = 0.f;
  for (int y = 12; y < view.height - 12; ++y)
    for (int x = 0; x < view.width; ++x) {
      worst = std::max(worst, std::abs(adaptive.at(x, y).a - reference.at(x, y).a));
      visible = std::max(visible, reference.at(x, y).a);
    }
  EXPECT_GT(visible, 0.5f);
  EXPECT_LE(worst, 1e-6f);
  // Three samples a ray at its ends (first - 1, first, last) and a few coarse ones between.
  EXPECT_LT(skipping.samples * 15, every.samples);
}

// A plate one voxel thick across the rays in empty space. Skipping along the rays alone would
// jump over it (a segment from air to air pre-integrates to nothing); the oracle marks its blocks
// as edges, so the rays slow down in time and the plate is as opaque as in the exact image, while
// the empty space around it is sampled far less.
TEST(AdaptiveSampling, TheOracleKeepsAThinPlateThatSkippingWouldMiss) {
  Volume volume = filledVolume({40, 48, 40}, 0);
  for (int k = 0; k < 40; ++k)
    for (int i = 0; i < 40; ++i) volume.voxels[volume.indexOf(i, 27, k)] = Voxel(3000);
  TransferFunction tf;
  tf.points = {{huOfDensity(1999), {1, 0.5, 0.2}, 0}, {huOfDensity(2000), {1, 0.5, 0.2}, 0.9}};
  const TfTable table = buildTable(tf);
  for (double angle : {0.0, 23.0}) {
    RenderParams p = adaptiveParams(Quality::medium, 3, 6);
    p.angleDeg = angle;
    AdaptiveSamplingStats stats, every;
    const Image adaptive = renderAdaptively(volume, table, p, &stats);
    RenderParams all = p;
    all.sampling.adaptiveSampling = AdaptiveSampling{0, 0, 0.02};
    const Image exact = renderAdaptively(volume, table, all, &every);
    EXPECT_LE(maxChannelDifference(adaptive, exact), 0.01f) << angle;
    EXPECT_LT(stats.samples * 2, every.samples) << angle;
    // Without the oracle's edges (an infinite tolerance) the plate is lost on most rays.
    RenderParams blind = p;
    blind.sampling.adaptiveSampling->tolerance = 1e9;
    const Image missed = renderAdaptively(volume, table, blind);
    EXPECT_GT(maxChannelDifference(missed, exact), 0.5f) << angle;
  }
}

// On the realistic phantom at the medium level's resolution: fewer samples than every ray at every
// sample, an image close to the exact pre-integrated one, and the same bytes for 1 and 2 threads.
TEST(AdaptiveSampling, SamplesLessOnTheRealisticPhantomAndIsDeterministic) {
  const Volume volume =
      generatePhantom({.dims = {64, 64, 140}, .seed = 7, .style = PhantomStyle::realistic}).volume;
  const TfTable table = buildTable(loadPresetOrFile("cta-vessels-bone"));
  RenderParams p = adaptiveParams(Quality::medium, 3, 6);
  p.sampling.filter = Filter::trilinear;
  p.angleDeg = 35;
  AdaptiveSamplingStats stats, every;
  Image twoThreads;
  {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    twoThreads = renderAdaptively(volume, table, p, &stats);
  }
  {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_EQ(renderAdaptively(volume, table, p).pixels, twoThreads.pixels);
  }
  RenderParams all = p;
  all.sampling.adaptiveSampling = AdaptiveSampling{0, 0, 0.02};
  const Image exact = renderAdaptively(volume, table, all, &every);
  EXPECT_LT(stats.samples, every.samples);
  EXPECT_GT(psnrDb(twoThreads, exact), 30.0);
}

TEST(AdaptiveSampling, IsRefusedForMipBadSettingsAndOwnTfLabels) {
  const Volume volume = filledVolume({8, 8, 8}, 1500);
  TransferFunction tf;
  tf.points = {{huOfDensity(1000), {1, 1, 1}, 0.1}};
  const TfTable table = buildTable(tf);
  RenderParams p = adaptiveParams(Quality::medium, 3, 6);
  p.compositing = Compositing::mip;
  EXPECT_THROW(renderAdaptively(volume, table, p), std::invalid_argument);
  p.compositing = Compositing::dvr;
  p.sampling.adaptiveSampling->rayLevels = kMaxAdaptiveLevels + 1;
  EXPECT_FALSE(samplingProblem(p.sampling).empty());
  EXPECT_THROW(renderAdaptively(volume, table, p), std::invalid_argument);
  p.sampling.adaptiveSampling->rayLevels = 2;  // fewer than the image's levels
  EXPECT_FALSE(samplingProblem(p.sampling).empty());
  p.sampling.adaptiveSampling->rayLevels = 6;
  p.sampling.adaptive = AdaptiveIntegration{};
  EXPECT_FALSE(samplingProblem(p.sampling).empty());
  p.sampling.adaptive.reset();
  p.sampling.adaptiveSampling->tolerance = std::nan("");
  EXPECT_FALSE(samplingProblem(p.sampling).empty());
}

}  // namespace
}  // namespace angio
