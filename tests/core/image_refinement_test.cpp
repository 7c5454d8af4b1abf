// Image-plane refinement (core/image_refinement.h) and the pixel mask it casts through
// (FastRenderOptions::pixels): masked pixels are the unmasked frame's to the bit and the others
// stay untouched, for every filter, MIP, labels and clipping; on analytic images the refinement
// reproduces a bilinear image from the lattice alone, a straight edge exactly at tolerance 0, and
// never misses a band as wide as the lattice step; on a phantom it is deterministic and close to
// the exact frame.
#include <cmath>
#include <functional>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "core/fast_raycaster.h"
#include "core/image_refinement.h"
#include "core/view_geometry.h"
#include "phantom/phantom.h"

namespace angio {
namespace {

using PixelFunction = std::function<glm::vec4(int x, int y)>;

// A "renderer" of an analytic image: writes f at the masked pixels, counts the pixels it cast.
struct AnalyticRenderer {
  PixelFunction f;
  std::uint64_t cast = 0;
  bool operator()(const std::vector<std::uint8_t>& mask, Image& image) {
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        if (mask[std::size_t(y) * image.width + x]) {
          image.at(x, y) = f(x, y);
          ++cast;
        }
    return true;
  }
};

float maxDifference(const Image& image, const PixelFunction& f) {
  float worst = 0.f;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const glm::vec4 d = glm::abs(image.at(x, y) - f(x, y));
      worst = std::max({worst, d.r, d.g, d.b, d.a});
    }
  return worst;
}

TEST(ImageRefinement, ABilinearImageComesFromTheLatticeAlone) {
  const PixelFunction f = [](int x, int y) {
    return glm::vec4(0.01f * x, 0.02f * y, 0.5f + 0.001f * x * y, 0.3f + 0.004f * x);
  };
  for (int levels : {1, 2, 4}) {
    AnalyticRenderer renderer{f};
    RefinementStats stats;
    // 61 x 38: neither side a multiple of the step, so the last cells are narrower.
    const Image image = refineImage(61, 38, {levels, 1e9}, std::ref(renderer), &stats);
    EXPECT_LE(maxDifference(image, f), 1e-5f) << levels;
    const int step = 1 << levels;
    // 0, step, 2 step ... up to the last index, and the last index.
    const auto line = [&](int size) { return (size - 1) / step + 1 + ((size - 1) % step != 0); };
    const std::uint64_t lattice = std::uint64_t(line(61) * line(38));
    EXPECT_EQ(stats.passes, 1);
    EXPECT_EQ(renderer.cast, lattice) << levels;
  }
}

// A half-plane of another colour: a cell whose four corners lie on one side lies wholly on it, so
// at tolerance 0 the image is exact; only cells the edge crosses are cast down to every pixel.
TEST(ImageRefinement, AStraightEdgeIsExactAtToleranceZero) {
  const PixelFunction f = [](int x, int y) {
    return 3 * x + 7 * y > 200 ? glm::vec4(0.9f, 0.8f, 0.7f, 1.f) : glm::vec4(0.1f, 0.f, 0.2f, 0.4f);
  };
  AnalyticRenderer renderer{f};
  RefinementStats stats;
  const Image image = refineImage(80, 50, {3, 0.0}, std::ref(renderer), &stats);
  EXPECT_EQ(maxDifference(image, f), 0.f);
  EXPECT_EQ(stats.passes, 4);
  EXPECT_LT(renderer.cast, 80u * 50u / 3);  // the edge's cells, not the image
}

// A band at least as wide as the lattice step holds a lattice row, so every cell it crosses has a
// corner in it and is refined: at tolerance 0 nothing of it is lost, wherever it lies.
TEST(ImageRefinement, ABandAsWideAsTheStepIsNeverMissed) {
  const int step = 4;
  for (int top = 0; top < 2 * step; ++top) {
    const PixelFunction f = [&](int, int y) {
      return y >= top + 10 && y < top + 10 + step ? glm::vec4(1.f) : glm::vec4(0.f);
    };
    AnalyticRenderer renderer{f};
    const Image image = refineImage(40, 40, {2, 0.0}, std::ref(renderer));
    EXPECT_EQ(maxDifference(image, f), 0.f) << top;
  }
}

TEST(ImageRefinement, OneRowOrColumnIsCastWhole) {
  const PixelFunction f = [](int x, int y) { return glm::vec4(0.1f * x, 0.1f * y, 0.f, 1.f); };
  for (auto [w, h] : {std::pair{1, 9}, std::pair{9, 1}, std::pair{1, 1}}) {
    AnalyticRenderer renderer{f};
    const Image image = refineImage(w, h, {2, 1e9}, std::ref(renderer));
    EXPECT_EQ(maxDifference(image, f), 0.f);
    EXPECT_EQ(renderer.cast, std::uint64_t(w * h));
  }
}

struct Scene {
  Volume volume =
      generatePhantom({.dims = {48, 48, 96}, .seed = 3, .style = PhantomStyle::realistic}).volume;
  TfTable table =
      buildTable({"bone and vessels",
                  {{-1024, {0, 0, 0}, 0}, {150, {1, 0.3f, 0.2f}, 0}, {400, {1, 1, 0.9f}, 0.5}}});
  SliceTiles tiles = buildSliceTiles(volume, Axis::k);
  TileClassification visible{tiles, singleTable(table), /*mip=*/true};
};

RenderParams sceneParams(Quality quality, double angle) {
  RenderParams p;
  p.angleDeg = angle;
  p.sampling = qualitySampling(quality);
  return p;
}

// Every third pixel in a diagonal pattern, and two whole rows.
std::vector<std::uint8_t> patternMask(int width, int height) {
  std::vector<std::uint8_t> mask(std::size_t(width) * height, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      mask[std::size_t(y) * width + x] = (x + 2 * y) % 3 == 0 || y == height / 2 || y == height / 2 + 1;
  return mask;
}

void expectMaskedPixelsExact(const Scene& scene, const RenderParams& p, const std::string& what) {
  const Image whole = renderFast(scene.volume, scene.visible, scene.table, p);
  const std::vector<std::uint8_t> mask = patternMask(whole.width, whole.height);
  const glm::vec4 untouched(7.f, -3.f, 5.f, 2.f);
  Image image = whole;
  std::fill(image.pixels.begin(), image.pixels.end(), untouched);
  FastRenderOptions options;
  options.pixels = &mask;
  options.recycle = &image;
  const Image masked = renderFast(scene.volume, scene.visible, scene.table, p, options);
  ASSERT_EQ(masked.width, whole.width);
  int differing = 0, touched = 0;
  for (std::size_t n = 0; n < mask.size(); ++n) {
    if (mask[n]) differing += masked.pixels[n] != whole.pixels[n];
    else touched += masked.pixels[n] != untouched;
  }
  EXPECT_EQ(differing, 0) << what;
  EXPECT_EQ(touched, 0) << what;
}

TEST(ImageRefinement, MaskedPixelsAreTheWholeFramesAndTheOthersStayUntouched) {
  const Scene scene;
  for (Quality quality : {Quality::fast, Quality::medium, Quality::high}) {
    RenderParams p = sceneParams(quality, 33);
    expectMaskedPixelsExact(scene, p, toString(quality));
    p.sampling.filter = Filter::trilinear;
    expectMaskedPixelsExact(scene, p, std::string(toString(quality)) + " trilinear");
    p.compositing = Compositing::mip;
    expectMaskedPixelsExact(scene, p, std::string(toString(quality)) + " MIP");
  }
  RenderParams clipped = sceneParams(Quality::medium, 70);
  clipped.clipping.crop = CropBox{{5, 5, 10}, {30, 40, 60}};
  expectMaskedPixelsExact(scene, clipped, "crop box");
}

TEST(ImageRefinement, RendersTheSameBytesForAnyThreadCount) {
  const Scene scene;
  RenderParams p = sceneParams(Quality::medium, 21);
  p.sampling.filter = Filter::trilinear;
  const RegionTables tables = singleTable(scene.table);
  Image one, two;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = renderRefined(scene.volume, scene.visible, tables, p, {2, 0.02});
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    two = renderRefined(scene.volume, scene.visible, tables, p, {2, 0.02});
  }
  EXPECT_TRUE(one.pixels == two.pixels);
}

// Against the exact frame: cast pixels are exact and filled ones within the tolerance's reach of
// their corners, so the refined image stays close (PSNR over the 8-bit output; at tolerance 0.02 a
// filled pixel is off by at most 5/255 unless the cell hides something between its corners).
TEST(ImageRefinement, StaysCloseToTheExactFrameOnAPhantom) {
  const Scene scene;
  const RegionTables tables = singleTable(scene.table);
  for (double angle : {0.0, 37.0, 100.0}) {
    RenderParams p = sceneParams(Quality::medium, angle);
    p.sampling.filter = Filter::trilinear;
    const Image exact = renderFast(scene.volume, scene.visible, scene.table, p);
    RefinementStats stats;
    const Image refined =
        renderRefined(scene.volume, scene.visible, tables, p, {2, 0.02}, {}, nullptr, &stats);
    EXPECT_GE(psnrDb(refined, exact), 35.0) << angle;
    EXPECT_GT(stats.interpolated, 0u) << angle;
    EXPECT_GE(psnrDb(renderRefined(scene.volume, scene.visible, tables, p, {2, 0.0}), exact),
              psnrDb(refined, exact))
        << angle;
  }
}

}  // namespace
}  // namespace angio
