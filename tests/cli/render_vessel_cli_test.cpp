// `angioray render` with VesselGlyph regions, the DVR+CPR hybrid and render sidecars, end to end
// on the small phantom and its ground-truth centerlines. Expectations come from the centerline
// geometry and from independent commands (`cpr`, plain `render`), never from the output under
// test itself.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/view_geometry.h"
#include "io/centerline_file.h"
#include "io/volume_reader.h"
#include "tests/support/file_bytes.h"
#include "tests/support/run_angioray.h"

namespace {

namespace fs = std::filesystem;
using angio::test_support::fileBytes;
using angio::test_support::ProgramRun;
using angio::test_support::runAngioray;

struct Rgb8 {
  int width = 0, height = 0;
  std::vector<unsigned char> bytes;  // RGB
  const unsigned char* at(int x, int y) const { return &bytes[3 * (std::size_t(y) * width + x)]; }
  bool colored(int x, int y) const { return at(x, y)[0] || at(x, y)[1] || at(x, y)[2]; }
  bool same(const Rgb8& other, int x, int y) const {
    return std::equal(at(x, y), at(x, y) + 3, other.at(x, y));
  }
};

Rgb8 readPng(const fs::path& file) {
  Rgb8 image;
  auto input = OIIO::ImageInput::open(file.string());
  if (!input) {
    ADD_FAILURE() << "cannot open " << file;
    return image;
  }
  image.width = input->spec().width;
  image.height = input->spec().height;
  image.bytes.resize(std::size_t(image.width) * image.height * 3);
  EXPECT_EQ(input->spec().nchannels, 3);
  input->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, image.bytes.data());
  return image;
}

int lineCount(const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); }

// A centerline point seen in a view: its continuous pixel position and lumen radius.
struct ProjectedPoint {
  double x = 0, y = 0, radiusMm = 0;
  bool inside = false;  // well inside the volume's domain
};

// The phantom (128 x 128 x 300, 3.2 mm voxel unit) and its centerlines, made once for all tests.
class RenderVesselCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("angioray-render-vessel-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    const ProgramRun run =
        runAngioray("phantom " + volume().string() +
                    " --size 128x128x300 --style simple --centerlines " + centerlines().string());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    writeTf(dir_ / "opaque.json", "opaque white", 1.0);
    writeTf(dir_ / "clear.json", "transparent", 0.0);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static void writeTf(const fs::path& file, const std::string& name, double opacity) {
    std::ofstream(file) << R"({"name": ")" << name
                        << R"(", "points": [{"hu": -1024, "color": [1, 1, 1], "opacity": )" << opacity
                        << R"(}, {"hu": 3071, "color": [1, 1, 1], "opacity": )" << opacity << "}]}";
  }
  static fs::path volume() { return dir_ / "phantom.mha"; }
  static fs::path centerlines() { return dir_ / "phantom.csv"; }
  static fs::path file(const std::string& name) { return dir_ / name; }
  static std::string vgBase(const std::string& quality = "medium") {
    return "render " + volume().string() + " --quality " + quality + " --centerlines " +
           centerlines().string();
  }

  // The centerline points projected into the view of the rendering model at `angleDeg` (axis k).
  static std::vector<ProjectedPoint> project(double angleDeg, angio::ViewGeometry& view) {
    const angio::Volume volume = angio::readVolume(RenderVesselCli::volume()).volume;
    angio::RenderParams params;
    params.angleDeg = angleDeg;
    params.sampling = angio::qualitySampling(angio::Quality::medium);
    view = angio::makeViewGeometry(volume, params);
    const angio::Centerlines lines = angio::toVolumeFrame(angio::loadCenterlines(centerlines()), volume);
    std::vector<ProjectedPoint> points;
    for (const auto& path : lines.paths) {
      for (const auto& point : path.points) {
        const glm::dvec3 p = point.positionMm - view.centre;
        ProjectedPoint projected;
        projected.x = glm::dot(p, view.right) / view.pixelMm + view.width / 2.0 - 0.5;
        projected.y = view.height / 2.0 - 0.5 - glm::dot(p, view.up) / view.pixelMm;
        projected.radiusMm = point.radiusMm;
        const glm::dvec3 margin(6.0);
        projected.inside = glm::all(glm::greaterThan(point.positionMm, margin)) &&
                           glm::all(glm::lessThan(point.positionMm, view.extent - margin));
        points.push_back(projected);
      }
    }
    return points;
  }

  static fs::path dir_;
};

fs::path RenderVesselCli::dir_;

// Distance (pixels) from (x, y) to the projected segment a-b.
double segmentDistance(double x, double y, const ProjectedPoint& a, const ProjectedPoint& b) {
  const glm::dvec2 p(x, y), pa(a.x, a.y), ab(b.x - a.x, b.y - a.y);
  const double length2 = glm::dot(ab, ab);
  const double s = length2 > 0 ? std::clamp(glm::dot(p - pa, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (pa + s * ab));
}

TEST_F(RenderVesselCli, OpaqueFocusStaysWithinItsRadiusOfTheProjectedCenterline) {
  const double angle = 30;
  const fs::path out = file("vg-opaque.png");
  const ProgramRun run = runAngioray(vgBase() +
                                     " --angle 30 --vg-focus circle:radius=2.0x --vg-context "
                                     "slab:front=20,back=20 --focus-tf " +
                                     file("opaque.json").string() + " --context-tf " +
                                     file("clear.json").string() + " --out " + out.string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Rgb8 image = readPng(out);
  angio::ViewGeometry view;
  const std::vector<ProjectedPoint> points = project(angle, view);
  ASSERT_EQ(image.width, view.width);
  ASSERT_EQ(image.height, view.height);

  // The focus is the union of round cones between consecutive centerline points (radius 2x the
  // lumen's); seen from any direction it lies within the larger end radius of the projected segment.
  // Consecutive CSV rows of two different paths (a jump of more than 4 px) are no segment.
  int colored = 0, tooFar = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (!image.colored(x, y)) continue;
      ++colored;
      bool near = false;
      for (std::size_t n = 0; n + 1 < points.size() && !near; ++n) {
        const double radiusPx =
            2.0 * std::max(points[n].radiusMm, points[n + 1].radiusMm) / view.pixelMm;
        const double gapPx = std::hypot(points[n + 1].x - points[n].x, points[n + 1].y - points[n].y);
        if (gapPx > 4) continue;  // the jump from one path's end to the next path's start
        near = segmentDistance(x, y, points[n], points[n + 1]) <= radiusPx + 1.0;
      }
      tooFar += !near;
    }
  }
  EXPECT_GT(colored, 500);
  EXPECT_EQ(tooFar, 0) << "of " << colored << " colored pixels";

  // And the vessel itself is there: the pixel under every centerline point inside the volume.
  int inside = 0, missing = 0;
  for (const ProjectedPoint& p : points) {
    if (!p.inside) continue;
    ++inside;
    missing += !image.colored(int(std::lround(p.x)), int(std::lround(p.y)));
  }
  EXPECT_GT(inside, 200);
  EXPECT_EQ(missing, 0) << "of " << inside;
}

TEST_F(RenderVesselCli, ImageMetadataRecordsTheVesselGlyphSettings) {
  const fs::path out = file("vg-metadata.png");
  const ProgramRun run = runAngioray(vgBase("fast") +
                                     " --vg-focus circle:radius=4mm --vg-context "
                                     "tube:radius=2.5x --vg-outside bone --half-vessel --out " +
                                     out.string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  auto input = OIIO::ImageInput::open(out.string());
  ASSERT_TRUE(input);
  const OIIO::ImageSpec& spec = input->spec();
  EXPECT_EQ(spec.get_string_attribute("angioray:vg_focus"), "circle:radius=4mm");
  EXPECT_EQ(spec.get_string_attribute("angioray:vg_context"), "tube:radius=2.5x");
  EXPECT_EQ(spec.get_string_attribute("angioray:vg_outside"), "tf Bone");
  EXPECT_EQ(spec.get_string_attribute("angioray:vg_half_vessel"), "on");
  EXPECT_EQ(spec.get_string_attribute("angioray:centerlines"), centerlines().string());
}

// Without --focus-tf/--context-tf the regions use --tf, the context faded (as the GUI's regions
// that follow the main TF): the sidecar records the fade.
TEST_F(RenderVesselCli, RegionTfsDefaultToTheMainTfWithTheContextFaded) {
  const fs::path out = file("vg-defaults.png");
  const ProgramRun run = runAngioray(vgBase("fast") + " --tf bone --out " + out.string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(out.string() + ".json");
  const nlohmann::json sidecar = nlohmann::json::parse(in);
  const nlohmann::json& vg = sidecar["vessel_glyph"];
  EXPECT_EQ(vg["focus_tf"]["name"], "Bone") << vg;
  EXPECT_EQ(vg["focus_tf"]["points"], vg["context_tf"]["points"]);
  EXPECT_DOUBLE_EQ(vg["context_tf"]["modulators"]["opacity_scale"].get<double>(), 0.2)
      << vg["context_tf"];
}

TEST_F(RenderVesselCli, ReferenceRaycasterGivesTheSameVesselGlyphImage) {
  const std::string common = vgBase("fast") +
                             " --angle 75 --vg-focus circle:radius=3mm "
                             "--vg-context tube:radius=15 --context-tf soft-tissue-context --cleft";
  const ProgramRun fast = runAngioray(common + " --out " + file("vg-fast.png").string());
  const ProgramRun reference = runAngioray(common + " --reference --out " + file("vg-ref.png").string());
  ASSERT_EQ(fast.exitCode, 0) << fast.output;
  ASSERT_EQ(reference.exitCode, 0) << reference.output;
  const Rgb8 a = readPng(file("vg-fast.png")), b = readPng(file("vg-ref.png"));
  EXPECT_EQ(a.bytes, b.bytes);
  EXPECT_GT(std::count_if(a.bytes.begin(), a.bytes.end(), [](unsigned char v) { return v > 0; }), 100);
}

TEST_F(RenderVesselCli, BadSpecsAndMissingCenterlinesAreOneLineErrors) {
  const std::string out = file("bad.png").string();
  for (const std::string options :
       {"--vg-focus circle", "--vg-focus circle:radius=", "--vg-focus circle:radius=0",
        "--vg-focus circle:radius=-2x", "--vg-focus square:radius=2", "--vg-focus circle:r=2",
        "--vg-focus circle:radius=2x,radius=3", "--vg-context slab:front=20",
        "--vg-context slab:front=20,back=abc", "--vg-context tube:width=3", "--vg-context cone",
        "--vg-context none:front=2", "--transition 2"}) {
    const ProgramRun run = runAngioray(vgBase() + " " + options + " --out " + out);
    EXPECT_NE(run.exitCode, 0) << options;
    EXPECT_EQ(lineCount(run.output), 1) << options << ": " << run.output;
    EXPECT_EQ(run.output.rfind("angioray: error: ", 0), 0u) << run.output;
  }
  const ProgramRun noFile = runAngioray("render " + volume().string() + " --centerlines " +
                                        file("missing.csv").string() + " --out " + out);
  EXPECT_NE(noFile.exitCode, 0);
  EXPECT_EQ(lineCount(noFile.output), 1) << noFile.output;
  EXPECT_NE(noFile.output.find("missing.csv"), std::string::npos) << noFile.output;
  const ProgramRun needsCenterlines =
      runAngioray("render " + volume().string() + " --cleft --out " + out);
  EXPECT_NE(needsCenterlines.exitCode, 0);
  EXPECT_EQ(lineCount(needsCenterlines.output), 1) << needsCenterlines.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(RenderVesselCli, SidecarReproducesEveryKindOfRenderByteForByte) {
  const std::vector<std::string> renders = {
      "render " + volume().string() + " --quality fast --angle 20 --tf cta-vessels-bone --ka 0.4",
      "render " + volume().string() + " --quality fast --mip --window 700 --level 200 --axis j",
      vgBase("fast") +
          " --angle 40 --vg-context slab:front=10,back=30,width=inf "
          "--focus-tf cta-vessels --context-tf soft-tissue-context --vg-outside bone --half-vessel",
      vgBase("fast") +
          " --angle 110 --hybrid-cpr --hybrid-path 1 --transition 5 "
          "--cpr-window 800 --cpr-level 250 --context-tf soft-tissue-context",
  };
  for (std::size_t n = 0; n < renders.size(); ++n) {
    const fs::path first = file("first-" + std::to_string(n) + ".png");
    const fs::path again = file("again-" + std::to_string(n) + ".png");
    const ProgramRun run = runAngioray(renders[n] + " --out " + first.string());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const fs::path sidecar = first.string() + ".json";
    ASSERT_TRUE(fs::exists(sidecar)) << renders[n];
    // The TF's whole content is in the sidecar, not only its name.
    EXPECT_NE(fileBytes(sidecar).find("\"points\""), std::string::npos);
    // From another working directory, to another file.
    const ProgramRun rerun =
        runAngioray("render --params " + sidecar.string() + " --out " + again.string());
    ASSERT_EQ(rerun.exitCode, 0) << rerun.output;
    EXPECT_EQ(fileBytes(first), fileBytes(again)) << renders[n];
    EXPECT_GT(fileBytes(first).size(), 100u);
  }
}

TEST_F(RenderVesselCli, SidecarErrorsAreOneLine) {
  std::ofstream(file("corrupt.json")) << "{\"angioray_render_sidecar\": 1, \"image\": ";
  std::ofstream(file("wrong.json")) << R"({"name": "a TF, not a sidecar", "points": []})";
  for (const std::string sidecar : {"absent.json", "corrupt.json", "wrong.json"}) {
    const ProgramRun run = runAngioray("render --params " + file(sidecar).string() + " --out " +
                                       file("never.png").string());
    EXPECT_NE(run.exitCode, 0) << sidecar;
    EXPECT_EQ(lineCount(run.output), 1) << run.output;
    EXPECT_NE(run.output.find(sidecar), std::string::npos) << run.output;
  }
  EXPECT_NE(runAngioray("render " + volume().string() + " --params x.json --out y.png").exitCode, 0);
  EXPECT_FALSE(fs::exists(file("never.png")));
}

TEST_F(RenderVesselCli, HybridShowsTheCprOnTheCenterlineAndTheContextDvrFarFromIt) {
  const double angle = 50;
  const std::string focusTf = "cta-vessels", contextTf = "soft-tissue-context", transitionMm = "6";
  const ProgramRun hybrid =
      runAngioray(vgBase() +
                  " --angle 50 --vg-focus circle:radius=2.0x --vg-context none"
                  " --vg-outside " +
                  contextTf + " --focus-tf " + focusTf + " --hybrid-cpr --transition " + transitionMm +
                  " --out " + file("hybrid.png").string());
  ASSERT_EQ(hybrid.exitCode, 0) << hybrid.output;
  // Independent paths: the projected CPR through the focus TF, and plain DVR with the context TF.
  const ProgramRun cpr = runAngioray("cpr " + volume().string() + " --centerlines " +
                                     centerlines().string() + " --mode projected --angle 50 --tf " +
                                     focusTf + " --no-overlay --out " + file("cpr.png").string());
  ASSERT_EQ(cpr.exitCode, 0) << cpr.output;
  const ProgramRun dvr =
      runAngioray("render " + volume().string() + " --quality medium --angle 50 --tf " + contextTf +
                  " --out " + file("dvr.png").string());
  ASSERT_EQ(dvr.exitCode, 0) << dvr.output;
  const Rgb8 h = readPng(file("hybrid.png")), c = readPng(file("cpr.png")), d = readPng(file("dvr.png"));
  ASSERT_EQ(h.width, c.width);
  ASSERT_EQ(h.height, c.height);
  ASSERT_EQ(h.width, d.width);

  angio::ViewGeometry view;
  const std::vector<ProjectedPoint> points = project(angle, view);
  int onCenterline = 0, differentFromCpr = 0;
  for (const ProjectedPoint& p : points) {
    if (!p.inside) continue;
    const int x = int(std::lround(p.x)), y = int(std::lround(p.y));
    ++onCenterline;
    differentFromCpr += !h.same(c, x, y);
  }
  EXPECT_GT(onCenterline, 200);
  EXPECT_EQ(differentFromCpr, 0) << "of " << onCenterline;

  // Far = beyond the largest focus radius (2 x 10.5 mm) plus the transition plus 2 pixels.
  const double farPx = (2 * 10.5 + 6) / view.pixelMm + 2;
  int far = 0, differentFromDvr = 0;
  for (int y = 0; y < h.height; ++y) {
    for (int x = 0; x < h.width; ++x) {
      bool isFar = true;
      for (const ProjectedPoint& p : points) isFar = isFar && std::hypot(x - p.x, y - p.y) > farPx;
      if (!isFar) continue;
      ++far;
      differentFromDvr += !h.same(d, x, y);
    }
  }
  EXPECT_GT(far, h.width * h.height / 3);
  EXPECT_EQ(differentFromDvr, 0) << "of " << far;
}

}  // namespace
