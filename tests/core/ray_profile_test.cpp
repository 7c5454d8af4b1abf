// The fast raycaster's profile (core/ray_profile.h) accounts for every sample of the domain: what
// each skipping level removed, what was evaluated, what early ray termination saved. Its counts
// are checked against each other and against the raycaster's own sample count with skipping off,
// and profiling must not change the image.
#include <gtest/gtest.h>

#include "core/fast_raycaster.h"
#include "io/tf_file.h"
#include "phantom/phantom.h"

namespace angio {
namespace {

struct ProfiledFrame {
  Image image;
  FastRenderStats stats;
};

class RayProfileTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    PhantomOptions options;
    options.dims = {48, 48, 112};
    volume_ = new Volume(generatePhantom(options).volume);
  }
  static void TearDownTestSuite() {
    delete volume_;
    volume_ = nullptr;
  }

  static RenderParams paramsAt(Quality quality, double ert) {
    RenderParams params;
    params.axis = Axis::k;
    params.angleDeg = 37;
    params.sampling = qualitySampling(quality);
    params.sampling.ert = ert;
    return params;
  }

  static ProfiledFrame render(const char* preset, const RenderParams& params,
                              FastRenderOptions options) {
    return render(loadPresetOrFile(preset), params, options);
  }
  static ProfiledFrame render(const TransferFunction& tf, const RenderParams& params,
                              FastRenderOptions options) {
    const TfTable table = buildTable(tf);
    const SliceTiles tiles = buildSliceTiles(*volume_, params.axis);
    const bool mip = params.compositing == Compositing::mip;
    const TileClassification visible(tiles, singleTable(table), mip);  // keeps a pointer to the tiles
    ProfiledFrame frame;
    frame.image = renderFast(*volume_, visible, table, params, options, &frame.stats);
    return frame;
  }

  static FastRenderOptions profiling(bool skipEmpty) {
    FastRenderOptions options;
    options.profile = true;
    options.skipEmpty = skipEmpty;
    return options;
  }

  static inline Volume* volume_ = nullptr;
};

TEST_F(RayProfileTest, ProfilingLeavesTheImageAlone) {
  for (Quality quality : {Quality::fast, Quality::medium, Quality::high}) {
    const RenderParams params = paramsAt(quality, 0.99);
    const ProfiledFrame plain = render("cta-vessels-bone", params, {});
    const ProfiledFrame profiled = render("cta-vessels-bone", params, profiling(true));
    EXPECT_FALSE(plain.stats.profiled);
    EXPECT_EQ(plain.stats.profile, RayProfile{});
    EXPECT_TRUE(profiled.stats.profiled);
    EXPECT_EQ(profiled.image.pixels, plain.image.pixels) << toString(quality);
    EXPECT_EQ(profiled.stats.samples, plain.stats.samples) << toString(quality);
  }
}

// Skipping and ERT off: every sample of the domain is evaluated, and the domain is exactly the
// samples the raycaster itself counts when it skips nothing.
TEST_F(RayProfileTest, WithoutSkippingOrTerminationEverySampleIsEvaluated) {
  for (Quality quality : {Quality::fast, Quality::medium, Quality::high}) {
    const ProfiledFrame frame = render("cta-vessels-bone", paramsAt(quality, 1.0), profiling(false));
    const RayProfile& p = frame.stats.profile;
    EXPECT_GT(p.domainSamples, 0u);
    EXPECT_EQ(p.domainSamples, frame.stats.samples) << toString(quality);
    EXPECT_EQ(p.evaluated, p.domainSamples) << toString(quality);
    EXPECT_EQ(p.skippedByGroups + p.skippedByTiles + p.skippedByCells, 0u);
    EXPECT_EQ(p.terminatedRays, 0u);
    EXPECT_EQ(p.savedByTermination(), 0u);
    EXPECT_GT(p.visible, 0u);
    EXPECT_LE(p.faint, p.visible);
    EXPECT_LT(p.visible, p.evaluated);  // the phantom's air and fat are transparent under this TF
  }
}

// Skipping on, ERT off: the skipped and the evaluated samples add up to the same domain, and the
// visible samples are the same ones (only provably transparent samples are skipped).
TEST_F(RayProfileTest, SkippedAndEvaluatedSamplesAddUpToTheDomain) {
  for (Quality quality : {Quality::fast, Quality::medium, Quality::high}) {
    const RenderParams params = paramsAt(quality, 1.0);
    const RayProfile all = render("cta-vessels-bone", params, profiling(false)).stats.profile;
    const RayProfile p = render("cta-vessels-bone", params, profiling(true)).stats.profile;
    EXPECT_EQ(p.domainSamples, all.domainSamples) << toString(quality);
    EXPECT_EQ(p.skippedByGroups + p.skippedByTiles + p.skippedByCells + p.evaluated, p.domainSamples)
        << toString(quality);
    EXPECT_GT(p.skippedByGroups + p.skippedByTiles, 0u);
    EXPECT_EQ(p.visible, all.visible) << toString(quality);
    EXPECT_EQ(p.faint, all.faint) << toString(quality);
    EXPECT_LE(p.rays, all.rays);  // rays are started at their first group not skipped
  }
}

// A TF that makes soft tissue opaque ends rays early: terminated rays are counted with the depth
// they took, and the samples behind them are what termination saved.
TEST_F(RayProfileTest, EarlyTerminationIsCountedWithItsDepth) {
  TransferFunction opaqueTissue;
  opaqueTissue.name = "opaque tissue";
  opaqueTissue.points = {{-1024, {0, 0, 0}, 0}, {-200, {1, 0.8f, 0.7f}, 0}, {0, {1, 0.8f, 0.7f}, 1}};
  const RenderParams params = paramsAt(Quality::medium, 0.99);
  const RayProfile p = render(opaqueTissue, params, profiling(true)).stats.profile;
  EXPECT_GT(p.terminatedRays, 0u);
  EXPECT_LE(p.terminatedRays, p.rays);
  EXPECT_GE(p.terminatedDepth, p.terminatedRays);  // at least one sample each
  EXPECT_GT(p.savedByTermination(), 0u);
  EXPECT_EQ(
      p.skippedByGroups + p.skippedByTiles + p.skippedByCells + p.evaluated + p.savedByTermination(),
      p.domainSamples);
}

TEST_F(RayProfileTest, OnlyPlainDvrIsProfiled) {
  RenderParams params = paramsAt(Quality::medium, 0.99);
  params.compositing = Compositing::mip;
  const ProfiledFrame mip = render("cta-vessels-bone", params, profiling(true));
  EXPECT_FALSE(mip.stats.profiled);
  EXPECT_EQ(mip.stats.profile, RayProfile{});
}

}  // namespace
}  // namespace angio
