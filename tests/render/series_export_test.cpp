// "Export rotation series" without a window: the angles of an arc, N numbered images whose
// sidecars carry their angles and whose pixels are the fast raycaster's image at that angle,
// cancel stopping the series, and the movie OpenCV writes (read back with VideoCapture).
#include "render/series_export.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <OpenImageIO/imagebuf.h>
#include <opencv2/videoio.hpp>

#include "core/fast_raycaster.h"
#include "phantom/phantom.h"
#include "core/slice_tiles.h"
#include "core/view_geometry.h"
#include "render/frame_renderer.h"
#include "io/input_error.h"
#include "render/recipe_json.h"
#include "io/tf_file.h"
#include "vessel/centerline.h"
#include "vessel/cpr_hybrid.h"
#include "vessel/cpr_layout.h"
#include "vessel/cpr_resample.h"
#include "vessel/vessel_glyph.h"

namespace angio {
namespace {

namespace fs = std::filesystem;

const Phantom& smallPhantomWithPaths() {
  static const Phantom phantom = [] {
    PhantomOptions options;
    options.style = PhantomStyle::simple;
    options.dims = {32, 32, 64};
    return generatePhantom(options);
  }();
  return phantom;
}

const Volume& smallPhantom() { return smallPhantomWithPaths().volume; }

// The DVR+CPR hybrid of one view made the plain way (vessel/cpr_hybrid.h compositeHybrid of the
// whole displayed CPR, not the in-place step the exports run): VesselGlyph DVR of all paths,
// their projected CPR in the focus footprint.
Image referenceHybrid(const Volume& volume, const Centerlines& centerlines, const RenderRecipe& s) {
  const VesselGlyphRecipe& vg = *s.vesselGlyph;
  const ViewGeometry view = makeViewGeometry(volume, s.params);
  const RayRegions regions = buildRayRegions(volume, view, centerlines, vg.settings);
  const TfTable focus = buildTable(vg.focusTf), context = buildTable(vg.contextTf);
  const RegionTables tables{&regions, &focus, &context, nullptr};
  const SliceTiles tiles = buildSliceTiles(volume, s.params.axis);
  const Image dvr = renderFast(volume, TileClassification(tiles, tables), tables, s.params);
  const CprLayout layout = layoutCpr(centerlines.paths, view, {CprMode::projected});
  CprDisplay display;
  display.centerlineMarker = display.ruler = false;
  display.windowLevel = *s.hybrid->grey;
  const Image cpr = displayCpr(layout, resampleCpr(volume, layout), display);
  return compositeHybrid(dvr, cpr, focusFootprint(regions), {s.hybrid->transitionMm, view.pixelMm});
}

std::vector<std::uint8_t> filePixels(const fs::path& file, int width, int height) {
  OIIO::ImageBuf image(file.string());
  EXPECT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::UINT8));
  EXPECT_EQ(image.spec().width, width);
  std::vector<std::uint8_t> pixels(std::size_t(width) * height * 3);
  image.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::UINT8, pixels.data());
  return pixels;
}

class SeriesExport : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("angioray_series_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    tf_ = loadPresetOrFile("cta-vessels-bone");
    base_.dataset = "phantom 32x32x64";
    base_.tf = tf_;
    base_.quality = Quality::high;
    base_.params.axis = Axis::k;
    base_.params.sampling = {1.0, 1.0, Filter::trilinear, 0.98};
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<fs::path> filesWithExtension(const std::string& extension) const {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir_))
      if (entry.path().extension() == extension) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
  }

  fs::path dir_;
  TransferFunction tf_;
  RenderRecipe base_;
};

TEST(SeriesAngles, FullTurnLeavesOutTheEndAndAnArcKeepsBothEnds) {
  EXPECT_EQ(seriesAngles(0, 360, 4), (std::vector<double>{0, 90, 180, 270}));
  EXPECT_EQ(seriesAngles(350, 90, 3), (std::vector<double>{350, 35, 80}));
  EXPECT_EQ(seriesAngles(10, -20, 3), (std::vector<double>{10, 0, 350}));
  EXPECT_EQ(seriesAngles(42, 360, 1), (std::vector<double>{42}));
}

TEST_F(SeriesExport, WritesNumberedImagesWhoseSidecarsHoldTheirAngles) {
  SeriesSpec spec;
  spec.count = 4;
  int lastDone = 0;
  SeriesCallbacks callbacks;
  callbacks.progress = [&](int done, int total) {
    EXPECT_EQ(done, lastDone + 1);
    EXPECT_EQ(total, 4);
    lastDone = done;
  };
  const SeriesResult result = exportRotationSeries(smallPhantom(), {}, base_, spec, dir_, callbacks);
  EXPECT_FALSE(result.cancelled);
  ASSERT_EQ(result.images.size(), 4u);
  EXPECT_EQ(filesWithExtension(".png").size(), 4u);
  EXPECT_EQ(filesWithExtension(".json").size(), 4u);
  EXPECT_EQ(result.images[0].filename(), "view-000.png");
  EXPECT_EQ(result.images[3].filename(), "view-003.png");

  const SliceTiles tiles = buildSliceTiles(smallPhantom(), Axis::k);
  const TfTable table = buildTable(tf_);
  const double expected[] = {0, 90, 180, 270};
  for (int n = 0; n < 4; ++n) {
    const RenderRecipe sidecar = loadRenderSidecar(sidecarPathFor(result.images[n]));
    EXPECT_DOUBLE_EQ(sidecar.params.angleDeg, expected[n]) << n;
    EXPECT_DOUBLE_EQ(sidecar.params.sampling.isd, 1.0);
    EXPECT_EQ(sidecar.tf.points.size(), tf_.points.size());
    // The file holds the raycaster's image at that angle, byte for byte.
    RenderParams params = base_.params;
    params.angleDeg = expected[n];
    const Image direct = renderFast(smallPhantom(), TileClassification(tiles, table), table, params);
    const std::vector<std::uint8_t> want = toRgb8(direct);
    OIIO::ImageBuf file(result.images[n].string());
    ASSERT_TRUE(file.read(0, 0, true, OIIO::TypeDesc::UINT8));
    ASSERT_EQ(file.spec().width, direct.width);
    std::vector<std::uint8_t> got(want.size());
    file.get_pixels(OIIO::ROI(0, direct.width, 0, direct.height, 0, 1, 0, 3), OIIO::TypeDesc::UINT8,
                    got.data());
    EXPECT_EQ(got, want) << n;
  }
}

TEST_F(SeriesExport, HybridSeriesHoldsTheHybridOfEachViewAndItsRecipe) {
  const Centerlines centerlines = toVolumeFrame(smallPhantomWithPaths().centerlines, smallPhantom());
  RenderRecipe base = base_;
  base.vesselGlyph =
      VesselGlyphRecipe{"phantom.csv", {}, tf_, loadPresetOrFile("soft-tissue-context"), std::nullopt};
  base.hybrid = HybridCprRecipe{"all", 2.0, kCtaLumenWindow};
  SeriesSpec spec;
  spec.count = 3;
  const SeriesResult result = exportRotationSeries(smallPhantom(), centerlines, base, spec, dir_, {});
  ASSERT_EQ(result.images.size(), 3u);
  long differFromPlain = 0;
  for (int n = 0; n < 3; ++n) {
    const RenderRecipe sidecar = loadRenderSidecar(sidecarPathFor(result.images[n]));
    ASSERT_TRUE(sidecar.hybrid.has_value()) << n;
    EXPECT_DOUBLE_EQ(sidecar.hybrid->transitionMm, 2.0);
    ASSERT_TRUE(sidecar.hybrid->grey.has_value());
    EXPECT_DOUBLE_EQ(sidecar.params.angleDeg, n * 120.0);
    const Image expected = referenceHybrid(smallPhantom(), centerlines, sidecar);
    EXPECT_EQ(filePixels(result.images[n], expected.width, expected.height), toRgb8(expected)) << n;
    RenderRecipe plain = sidecar;
    plain.hybrid.reset();
    const std::vector<std::uint8_t> vesselGlyph =
        toRgb8(renderRecipe(smallPhantom(), centerlines, plain));
    differFromPlain += vesselGlyph != toRgb8(expected);
  }
  EXPECT_EQ(differFromPlain, 3);  // every view shows the CPR somewhere
}

TEST_F(SeriesExport, CancelStopsTheSeries) {
  SeriesSpec spec;
  spec.count = 10;
  std::atomic<bool> cancel{false};
  SeriesCallbacks callbacks;
  callbacks.cancel = &cancel;
  callbacks.progress = [&](int done, int) {
    if (done == 2) cancel.store(true);
  };
  // A series the user had: a cancelled one must leave it as it was (all or nothing).
  fs::create_directories(dir_);
  std::ofstream(dir_ / "view-000.png", std::ios::binary) << "the earlier series";
  const SeriesResult result = exportRotationSeries(smallPhantom(), {}, base_, spec, dir_, callbacks);
  EXPECT_TRUE(result.cancelled);
  EXPECT_TRUE(result.images.empty());
  EXPECT_EQ(filesWithExtension(".png").size(), 1u);
  EXPECT_TRUE(filesWithExtension(".json").empty());
  std::ifstream earlier(dir_ / "view-000.png", std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(earlier), {}), "the earlier series");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1)
      << "no scratch folder left";
  EXPECT_NE(result.summary.find("cancelled"), std::string::npos) << result.summary;
}

TEST_F(SeriesExport, MovieHoldsEveryView) {
  SeriesSpec spec;
  spec.count = 6;
  spec.format = "tif";
  spec.movie = true;
  const SeriesResult result = exportRotationSeries(smallPhantom(), {}, base_, spec, dir_, {});
  EXPECT_EQ(filesWithExtension(".tif").size(), 6u);
  if (result.movie.empty()) GTEST_SKIP() << result.movieNote;
  ASSERT_TRUE(fs::exists(result.movie));
  EXPECT_GT(fs::file_size(result.movie), 0u);
  cv::VideoCapture capture(result.movie.string());
  if (!capture.isOpened()) GTEST_SKIP() << "OpenCV cannot read back " << result.movie;
  int frames = 0;
  for (cv::Mat frame; capture.read(frame);) {
    ++frames;
    EXPECT_EQ(frame.cols % 2, 0);  // H.264's chroma needs even sides
    EXPECT_EQ(frame.rows % 2, 0);
  }
  EXPECT_EQ(frames, 6) << result.movieNote;
  // Written under a temporary name, then renamed: nothing of it is left beside the movie.
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos) << entry.path();
}

// A movie the user has stays as it was while the new one is written (and would, had the series
// failed half-way); only the finished movie replaces it.
TEST_F(SeriesExport, AnExistingMovieIsReplacedOnlyByTheFinishedOne) {
  SeriesSpec spec;
  spec.count = 4;
  spec.movie = true;
  const std::string old = "the user's earlier movie";
  fs::create_directories(dir_);
  for (const char* name : {"view.mp4", "view.avi"}) std::ofstream(dir_ / name) << old;
  const auto contents = [&](const char* name) {
    std::ifstream in(dir_ / name);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  bool untouchedMidway = true;
  SeriesCallbacks callbacks;
  callbacks.progress = [&](int done, int) {
    if (done == 2) untouchedMidway = contents("view.mp4") == old && contents("view.avi") == old;
  };
  const SeriesResult result = exportRotationSeries(smallPhantom(), {}, base_, spec, dir_, callbacks);
  EXPECT_TRUE(untouchedMidway);
  if (result.movie.empty()) GTEST_SKIP() << result.movieNote;
  EXPECT_NE(contents(result.movie.filename().string().c_str()), old);
}

TEST_F(SeriesExport, BadSpecIsAnInputErrorNamingTheFolder) {
  SeriesSpec spec;
  spec.count = 0;
  try {
    exportRotationSeries(smallPhantom(), {}, base_, spec, dir_, {});
    ADD_FAILURE() << "accepted 0 views";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(dir_.string()), std::string::npos) << error.what();
  }
  spec.count = 3;
  spec.format = "gif";
  EXPECT_THROW(exportRotationSeries(smallPhantom(), {}, base_, spec, dir_, {}), InputError);
}

}  // namespace
}  // namespace angio
