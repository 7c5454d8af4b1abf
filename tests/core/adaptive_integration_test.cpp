// Adaptive integration (seed 000 sec. 4.3, core/adaptive_integration.h) against analytic cases: a
// constant medium is resolved by the initial intervals (no refinement, and the emission-absorption
// integral's closed form), a shell as thick as the node spacing is never missed, and a tighter
// tolerance brings the image closer to the converged exact one.
#include <cmath>

#include <gtest/gtest.h>

#include "core/adaptive_integration.h"
#include "core/reference_raycaster.h"
#include "core/view_geometry.h"
#include "io/tf_file.h"
#include "phantom/phantom.h"
#include "tests/support/filled_volume.h"

namespace angio {
namespace {

using test_support::filledVolume;

// Visible (opacity `a`, colour `color`) from density 1000 up, transparent below.
TfTable stepTf(double a, glm::vec3 color) {
  TransferFunction tf;
  tf.points = {{huOfDensity(0), color, 0}, {huOfDensity(999), color, 0}, {huOfDensity(1000), color, a}};
  return buildTable(tf);
}

RenderParams adaptiveParams(double tolerance, double initialStep, Filter filter = Filter::trilinear) {
  RenderParams p;
  p.sampling = qualitySampling(Quality::medium);
  p.sampling.filter = filter;
  p.sampling.ert = 1.0;
  p.shading.enabled = false;
  p.sampling.adaptive = AdaptiveIntegration{tolerance, initialStep, 0.125};
  return p;
}

TEST(AdaptiveIntegration, AConstantMediumNeedsNoRefinementAndIntegratesInClosedForm) {
  const Volume volume = filledVolume({24, 24, 8}, 1500);
  const glm::vec3 color(0.8f, 0.5f, 0.2f);
  const double a = 0.05;  // per voxel unit
  const TfTable table = stepTf(a, color);
  const RenderParams p = adaptiveParams(0.01, 4.0);
  AdaptiveIntegrationStats stats;
  const Image image = renderAdaptive(volume, singleTable(table), p, &stats);
  const ViewGeometry view = makeViewGeometry(volume, p);
  std::uint64_t rays = 0, initialNodes = 0;
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x) {
      const SampleRange samples = sampleRange(view, view.rayOrigin(x, y));
      if (samples.empty()) continue;
      ++rays;
      const double length = double(samples.last - samples.first) * p.sampling.osd;
      const long intervals = std::max(1L, long(std::ceil(length / 4.0 - 1e-9)));
      initialNodes += 2 * intervals + 1;
      // Emission-absorption of a constant medium over `length`: alpha = 1 - (1 - a)^length, colour
      // c alpha. Simpson's rule on the initial intervals (h <= 4, k h <= 0.21) is within 1e-4.
      const glm::vec4 pixel = image.at(x, y);
      const double alpha = 1.0 - std::pow(1.0 - a, length);
      EXPECT_NEAR(pixel.a, alpha, 1e-4) << x << "," << y;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(pixel[c], color[c] * alpha, 1e-4) << x << "," << y;
    }
  ASSERT_GT(rays, 0u);
  EXPECT_EQ(stats.passes, rays);  // one pass each: nothing refined
  EXPECT_EQ(stats.nodes, initialNodes);
}

// A slab two voxels thick (nearest filter: exactly 2 units along j) in empty space: with the
// initial step 4 the nodes are 2 apart along every ray, so every ray that crosses the slab sees it;
// with the initial step 8 (nodes 4 apart) some miss it, as the seed warns.
TEST(AdaptiveIntegration, AShellAsThickAsTheNodeSpacingIsNeverMissed) {
  Volume volume = filledVolume({48, 48, 4}, 0);
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 48; ++i)
      for (int j : {23, 24}) volume.voxels[volume.indexOf(i, j, k)] = Voxel(2000);
  const TfTable table = stepTf(0.5, glm::vec3(1.f));
  int missed = 0;
  for (double angle : {0.0, 17.0, 33.0, 52.0}) {
    int seen = 0;
    for (double initialStep : {4.0, 8.0}) {
      RenderParams p = adaptiveParams(0.01, initialStep, Filter::nearest);
      p.angleDeg = angle;
      const Image image = renderAdaptive(volume, singleTable(table), p);
      const Image exact = renderReference(volume, table, [&] {
        RenderParams q = p;
        q.sampling.adaptive.reset();
        q.sampling.osd = 0.05;
        return q;
      }());
      for (std::size_t n = 0; n < image.pixels.size(); ++n) {
        if (exact.pixels[n].a < 0.05f) continue;  // a ray that does not cross the slab
        const bool sees = image.pixels[n].a > 0.f;
        if (initialStep == 4.0) {
          EXPECT_TRUE(sees) << "angle " << angle << " pixel " << n;
          seen += sees;
        } else {
          missed += !sees;
        }
      }
    }
    EXPECT_GT(seen, 0) << angle;
  }
  EXPECT_GT(missed, 0) << "the coarser nodes should miss some rays";
}

double rmsDifference(const Image& a, const Image& b) {
  double sum = 0;
  for (std::size_t n = 0; n < a.pixels.size(); ++n)
    for (int c = 0; c < 3; ++c) sum += std::pow(double(a.pixels[n][c] - b.pixels[n][c]), 2);
  return std::sqrt(sum / (3.0 * a.pixels.size()));
}

TEST(AdaptiveIntegration, ATighterToleranceComesCloserToTheConvergedImageWithMoreNodes) {
  const Volume volume =
      generatePhantom({.dims = {40, 40, 90}, .seed = 2, .style = PhantomStyle::realistic}).volume;
  const TfTable table = buildTable(loadPresetOrFile("cta-vessels-bone"));
  RenderParams converged = adaptiveParams(0.01, 2.0);
  converged.sampling.adaptive.reset();
  converged.sampling.osd = 0.05;
  converged.shading.enabled = true;
  const Image exact = renderReference(volume, table, converged);
  double previousError = 1e9;
  std::uint64_t previousNodes = 0;
  for (double tolerance : {0.1, 0.01, 0.001}) {
    RenderParams p = adaptiveParams(tolerance, 2.0);
    p.shading.enabled = true;
    AdaptiveIntegrationStats stats;
    const double error = rmsDifference(renderAdaptive(volume, singleTable(table), p, &stats), exact);
    EXPECT_LT(error, previousError) << tolerance;
    EXPECT_GT(stats.nodes, previousNodes) << tolerance;
    previousError = error;
    previousNodes = stats.nodes;
  }
  EXPECT_LT(previousError, 0.01);
}

TEST(AdaptiveIntegration, IsRefusedForMipAndVesselGlyphRegions) {
  const Volume volume = filledVolume({8, 8, 8}, 1500);
  const TfTable table = stepTf(0.1, glm::vec3(1.f));
  RenderParams p = adaptiveParams(0.01, 4.0);
  p.compositing = Compositing::mip;
  EXPECT_THROW(renderAdaptive(volume, singleTable(table), p), std::invalid_argument);
  p.compositing = Compositing::dvr;
  p.sampling.adaptive->initialStep = 0.01;  // below the minimum step
  EXPECT_THROW(renderAdaptive(volume, singleTable(table), p), std::invalid_argument);
  p.sampling.adaptive.reset();
  EXPECT_THROW(renderAdaptive(volume, singleTable(table), p), std::invalid_argument);
}

}  // namespace
}  // namespace angio
