// The DVR+CPR hybrid in the workstation through the headless twin: the CPR section's checkbox turns
// the shown VesselGlyph image into the hybrid, which differs from the VesselGlyph image inside the
// focus footprint and equals it outside the footprint and its transition band; an export writes the
// shown image with a sidecar from which `angioray render --params` (another process, reading the
// files) renders the same pixels; a session carries the hybrid's settings (path, band, coloring)
// in and out.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <OpenImageIO/imagebuf.h>

#include "core/view_geometry.h"
#include "io/centerline_file.h"
#include "render/recipe_json.h"
#include "io/volume_reader.h"
#include "tests/support/phantom_folder_test.h"
#include "tests/support/run_angioray.h"
#include "vessel/cpr_hybrid.h"
#include "vessel/cpr_layout.h"
#include "vessel/vessel_glyph.h"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using angio::test_support::runAngioray;

// Tall enough for the side panel down to the Session section without scrolling.
const std::string kWindow = " --size 1000x1800 --timeout 120";

std::string at(const Json& rect, float dx = 8) {
  char text[64];
  std::snprintf(text, sizeof text, "[%.1f, %.1f]", rect[0].get<float>() + dx,
                (rect[1].get<float>() + rect[3].get<float>()) / 2);
  return text;
}
std::string middle(const Json& rect) {
  return at(rect, (rect[2].get<float>() - rect[0].get<float>()) / 2);
}

struct Rgb8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  bool samePixel(const Rgb8& other, std::size_t n) const {
    return rgb[3 * n] == other.rgb[3 * n] && rgb[3 * n + 1] == other.rgb[3 * n + 1] &&
           rgb[3 * n + 2] == other.rgb[3 * n + 2];
  }
};

Rgb8 readRgb8(const fs::path& file) {
  OIIO::ImageBuf image(file.string());
  EXPECT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::UINT8)) << file;
  Rgb8 out{image.spec().width, image.spec().height, {}};
  out.rgb.resize(std::size_t(out.width) * out.height * 3);
  image.get_pixels(OIIO::ROI(0, out.width, 0, out.height, 0, 1, 0, 3), OIIO::TypeDesc::UINT8,
                   out.rgb.data());
  return out;
}

// FNV-1a, as the app's report checksums the shown frame's RGB bytes.
std::string checksum(const Rgb8& image) {
  std::uint64_t hash = 1469598103934665603ull;
  for (std::uint8_t byte : image.rgb) hash = (hash ^ byte) * 1099511628211ull;
  return std::to_string(hash);
}

// Pixels within `bandPx` (image-plane distance) of a footprint pixel.
std::vector<std::uint8_t> dilated(const std::vector<std::uint8_t>& footprint, int width, int height,
                                  double bandPx) {
  std::vector<std::uint8_t> out(footprint.size(), 0);
  const int reach = int(std::ceil(bandPx));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (!footprint[std::size_t(y) * width + x]) continue;
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u >= 0 && v >= 0 && u < width && v < height && dx * dx + dy * dy <= bandPx * bandPx)
            out[std::size_t(v) * width + u] = 1;
        }
    }
  return out;
}

// Where the hybrid may differ from the VesselGlyph image: the paths' focus footprint in the
// sidecar's view (computed here from the files), and the transition band around it.
struct Cut {
  std::vector<std::uint8_t> footprint, reach;
};

Cut cutOf(const fs::path& sidecarFile) {
  const angio::RenderRecipe sidecar = angio::loadRenderSidecar(sidecarFile);
  const angio::Volume volume = angio::readVolume(sidecar.dataset).volume;
  angio::Centerlines centerlines =
      angio::toVolumeFrame(angio::loadCenterlines(sidecar.vesselGlyph->centerlines), volume);
  centerlines.paths = angio::selectPaths(centerlines, sidecar.hybrid->path);
  const angio::ViewGeometry view = angio::makeViewGeometry(volume, sidecar.params);
  Cut cut;
  cut.footprint = angio::focusFootprint(
      angio::buildRayRegions(volume, view, centerlines, sidecar.vesselGlyph->settings));
  // The band: pixel centres nearer than T to a footprint pixel centre (vessel/cpr_hybrid.h).
  cut.reach = dilated(cut.footprint, view.width, view.height,
                      sidecar.hybrid->transitionMm / view.pixelMm + 1e-6);
  return cut;
}

struct Comparison {
  long footprint = 0, changedInFootprint = 0, band = 0, changedInBand = 0, changedOutside = 0;
};

Comparison compare(const Rgb8& hybrid, const Rgb8& plain, const Cut& cut) {
  Comparison c;
  for (std::size_t n = 0; n < cut.footprint.size(); ++n) {
    const bool changed = !hybrid.samePixel(plain, n);
    if (cut.footprint[n]) ++c.footprint, c.changedInFootprint += changed;
    else if (cut.reach[n]) ++c.band, c.changedInBand += changed;
    else c.changedOutside += changed;
  }
  return c;
}

class GuiHybrid : public angio::test_support::PhantomFolderTest {
 protected:
  const char* folderPrefix() const override { return "gui-hybrid"; }
  std::string gui(const std::string& extra) const {
    return "gui " + file("phantom.nrrd") + " --headless" + kWindow + " --centerlines " +
           file("phantom.csv") + extra;
  }
  Json startLayout(const std::string& extra = "") {
    const auto run = runAngioray(gui(extra + " --state-out " + file("start.json")));
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return readJson("start.json")["runtime"]["layout"];
  }
  angio::test_support::ProgramRun runScript(const std::string& steps, const std::string& extra = "") {
    std::ofstream(dir / "script.json") << steps;
    return runAngioray(gui(extra + " --script " + file("script.json")));
  }
  // Steps typing `path` into the export field and exporting, then waiting for the export.
  std::string exportSteps(const Json& layout, const std::string& name) const {
    return R"({"click": )" + middle(layout["export_path"]) + R"(}, {"key": "Ctrl+A"}, {"text": ")" +
           file(name) + R"("}, {"key": "Enter"}, {"click": )" + middle(layout["export_button"]) +
           R"(}, {"wait_level": "high"})";
  }
  std::string saveSessionSteps(const Json& layout, const std::string& name) const {
    return R"({"click": )" + middle(layout["session_path"]) + R"(}, {"key": "Ctrl+A"}, {"text": ")" +
           file(name) + R"("}, {"key": "Enter"}, {"click": )" + middle(layout["session_save"]) +
           R"(}, {"wait_ms": 50})";
  }
  // `render --params` of an export's sidecar, into another file; its pixels.
  Rgb8 rerender(const std::string& name) {
    const auto run =
        runAngioray("render --params " + file(name + ".json") + " --out " + file("again-" + name));
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return readRgb8(dir / ("again-" + name));
  }
};

TEST_F(GuiHybrid, CheckboxShowsTheCprInTheFootprintAndTheExportIsWhatRenderParamsRenders) {
  const Json layout = startLayout();
  ASSERT_TRUE(layout.contains("cpr_hybrid")) << layout;
  const std::string steps = R"([
    {"click": )" + at(layout["vg_enable"]) +
                            R"(}, {"move": [5, 5]}, {"wait_level": "high"},
    )" + exportSteps(layout, "plain.png") +
                            R"(, {"state": ")" + file("plain.json") + R"("},
    {"click": )" + at(layout["cpr_hybrid"]) +
                            R"(}, {"move": [5, 5]}, {"wait_level": "high"},
    {"state": ")" + file("hybrid.json") +
                            R"("},
    )" + exportSteps(layout, "hybrid.png") +
                            R"(, {"state": ")" + file("exported.json") + R"("}])";
  const auto run = runScript(steps);
  ASSERT_EQ(run.exitCode, 0) << run.output;

  const Json plain = readJson("plain.json"), hybrid = readJson("hybrid.json"),
             exported = readJson("exported.json");
  EXPECT_TRUE(plain["runtime"]["vessel_glyph"]["rendering"].get<bool>());
  EXPECT_FALSE(plain["runtime"]["vessel_glyph"]["hybrid"]["rendering"].get<bool>());
  const Json& state = hybrid["runtime"]["vessel_glyph"]["hybrid"];
  EXPECT_TRUE(state["enabled"].get<bool>()) << state;
  EXPECT_TRUE(state["rendering"].get<bool>()) << state;
  EXPECT_EQ(hybrid["runtime"]["shown"]["level"], "high");
  EXPECT_NE(hybrid["runtime"]["shown"]["checksum"], plain["runtime"]["shown"]["checksum"]);
  // The export fields did not move when the hybrid's controls appeared (the script clicked them).
  EXPECT_EQ(hybrid["runtime"]["layout"]["export_button"], layout["export_button"]);
  EXPECT_NE(exported["runtime"]["message"].get<std::string>().find("exported"), std::string::npos)
      << exported["runtime"]["message"];

  // The export is the shown high image (export isd 0.5 = the high level's), the sidecar says hybrid.
  const Rgb8 hybridPng = readRgb8(dir / "hybrid.png"), plainPng = readRgb8(dir / "plain.png");
  EXPECT_EQ(checksum(hybridPng), hybrid["runtime"]["shown"]["checksum"]);
  EXPECT_EQ(checksum(plainPng), plain["runtime"]["shown"]["checksum"]);
  const Json sidecar = readJson("hybrid.png.json");
  ASSERT_TRUE(sidecar["hybrid_cpr"].is_object()) << sidecar["hybrid_cpr"];
  EXPECT_EQ(sidecar["hybrid_cpr"]["path"], "all");
  EXPECT_EQ(sidecar["hybrid_cpr"]["display"], "grey");  // the CPR section's default: CTA lumen
  EXPECT_DOUBLE_EQ(sidecar["hybrid_cpr"]["window"].get<double>(), 800);
  EXPECT_TRUE(readJson("plain.png.json")["hybrid_cpr"].is_null());
  EXPECT_TRUE(readJson("plain.png.json")["vessel_glyph"].is_object());

  // Another process from the files alone: the same pixels.
  EXPECT_EQ(rerender("hybrid.png").rgb, hybridPng.rgb);
  EXPECT_EQ(rerender("plain.png").rgb, plainPng.rgb);

  // Hard edge (transition 0): changed inside the footprint, untouched outside it.
  const Comparison c = compare(hybridPng, plainPng, cutOf(dir / "hybrid.png.json"));
  std::printf("footprint %ld px, %ld changed; band %ld px, %ld changed; outside %ld changed\n",
              c.footprint, c.changedInFootprint, c.band, c.changedInBand, c.changedOutside);
  EXPECT_GT(c.footprint, 200);
  EXPECT_GT(c.changedInFootprint, c.footprint / 2);
  EXPECT_EQ(c.changedOutside, 0);
}

TEST_F(GuiHybrid, AnotherDatasetDropsTheCenterlinesVesselGlyphCprAndTheEditedTfAndSaysSo) {
  const auto other = runAngioray("phantom " + file("other.nrrd") + " --size 64x64x128 --style simple");
  ASSERT_EQ(other.exitCode, 0) << other.output;
  const Json layout = startLayout();
  const std::string steps = R"([
    {"click": )" + at(layout["vg_enable"]) +
                            R"(}, {"click": )" + at(layout["cpr_hybrid"]) + R"(}, {"click": )" +
                            at(layout["cpr_shown"]) + R"(}, {"double_click": )" +
                            middle(layout["tf_plot"]) +
                            R"(}, {"move": [5, 5]}, {"wait_level": "high"},
    {"state": ")" + file("before.json") +
                            R"("}, {"open": ")" + file("other.nrrd") +
                            R"("}, {"wait_level": "high"}, {"state": ")" + file("after.json") + R"("}])";
  const auto run = runScript(steps);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json before = readJson("before.json"), after = readJson("after.json");
  ASSERT_TRUE(before["runtime"]["vessel_glyph"]["hybrid"]["rendering"].get<bool>()) << before["runtime"];
  ASSERT_TRUE(before["state"]["cpr"]["shown"].get<bool>());
  ASSERT_EQ(before["state"]["tf_preset"], "") << "the double click should have edited the TF";

  const Json& state = after["state"];
  EXPECT_EQ(state["dataset"], file("other.nrrd"));
  EXPECT_FALSE(state["vessel_glyph"]["enabled"].get<bool>());
  EXPECT_EQ(state["vessel_glyph"]["centerlines"], "");
  EXPECT_FALSE(state["cpr"]["shown"].get<bool>());
  EXPECT_FALSE(state["cpr"]["hybrid"].get<bool>());
  EXPECT_EQ(state["tf_preset"], readJson("start.json")["state"]["tf_preset"]);
  EXPECT_TRUE(after["runtime"]["tf_undo_available"].get<bool>());  // the edited TF one undo away
  const Json& shown = after["runtime"]["shown"];
  EXPECT_EQ(shown["level"], "high");
  EXPECT_GT(shown["samples"].get<long>(), 0);  // the new volume rendered, not a blank view
  EXPECT_EQ(after["runtime"]["vessel_glyph"]["paths"], 0);
  const std::string message = after["runtime"]["message"];
  for (const char* said : {"dropped with the old dataset", "4 vessel paths", "the centerline file",
                           "VesselGlyph", "the CPR view", "the edited TF gave way"})
    EXPECT_NE(message.find(said), std::string::npos) << said << " not in: " << message;
}

TEST_F(GuiHybrid, SessionCarriesPathBandAndColoringInAndOut) {
  // A session the app saved itself, with the hybrid's settings edited in.
  const Json start = startLayout();
  const auto save = runScript(R"([)" + saveSessionSteps(start, "base.json") + "]");
  ASSERT_EQ(save.exitCode, 0) << save.output;
  Json session = readJson("base.json");
  ASSERT_TRUE(session["cpr"].is_object()) << session;
  EXPECT_FALSE(session["cpr"]["hybrid"].get<bool>());
  session["cpr"].update(
      Json{{"hybrid", true}, {"path", 0}, {"transition_mm", 3}, {"colouring", "calcium"}});
  session["cpr"].erase("window");  // as a session of before the grey window was kept: the
  session["cpr"].erase("level");   // coloring's preset applies

  std::ofstream(dir / "in.json") << session.dump();

  const Json layout = startLayout(" --session " + file("in.json"));
  const std::string steps = R"([{"wait_level": "high"}, {"state": ")" + file("hybrid.json") + R"("},
    )" + exportSteps(layout, "hybrid.png") +
                            ", " + saveSessionSteps(layout, "out.json") + "]";
  const auto run = runScript(steps, " --session " + file("in.json"));
  ASSERT_EQ(run.exitCode, 0) << run.output;

  const Json hybrid = readJson("hybrid.json");
  EXPECT_TRUE(
      hybrid["runtime"]["vessel_glyph"]["enabled"].get<bool>());  // the hybrid implies VesselGlyph
  const Json& state = hybrid["runtime"]["vessel_glyph"]["hybrid"];
  EXPECT_TRUE(state["rendering"].get<bool>()) << state;
  EXPECT_EQ(state["path"], 0);
  EXPECT_DOUBLE_EQ(state["transition_mm"].get<double>(), 3);
  EXPECT_EQ(state["colouring"], "calcium");

  const Json sidecar = readJson("hybrid.png.json");
  EXPECT_EQ(sidecar["hybrid_cpr"]["path"], "0");
  EXPECT_DOUBLE_EQ(sidecar["hybrid_cpr"]["transition_mm"].get<double>(), 3);
  EXPECT_DOUBLE_EQ(sidecar["hybrid_cpr"]["window"].get<double>(), 1800);
  EXPECT_DOUBLE_EQ(sidecar["hybrid_cpr"]["level"].get<double>(), 700);
  const Rgb8 hybridPng = readRgb8(dir / "hybrid.png");
  EXPECT_EQ(checksum(hybridPng), hybrid["runtime"]["shown"]["checksum"]);  // what the window showed
  EXPECT_EQ(rerender("hybrid.png").rgb, hybridPng.rgb);

  // The VesselGlyph image of the same recipe without the hybrid, from the CLI.
  Json plainSidecar = sidecar;
  plainSidecar["hybrid_cpr"] = nullptr;
  std::ofstream(dir / "vg.png.json") << plainSidecar.dump();
  const Rgb8 plain = rerender("vg.png");
  const Comparison c = compare(hybridPng, plain, cutOf(dir / "hybrid.png.json"));
  std::printf(
      "path 0, 3 mm band: footprint %ld px, %ld changed; band %ld px, %ld changed; outside %ld "
      "changed\n",
      c.footprint, c.changedInFootprint, c.band, c.changedInBand, c.changedOutside);
  EXPECT_GT(c.footprint, 100);
  EXPECT_GT(c.changedInFootprint, c.footprint / 2);
  EXPECT_GT(c.changedInBand, 0);  // the CPR fades out over the band
  EXPECT_EQ(c.changedOutside, 0);

  const Json saved = readJson("out.json")["cpr"];
  EXPECT_TRUE(saved["hybrid"].get<bool>()) << saved;
  EXPECT_EQ(saved["path"], 0);
  EXPECT_DOUBLE_EQ(saved["transition_mm"].get<double>(), 3);
  EXPECT_EQ(saved["colouring"], "calcium");
}

TEST_F(GuiHybrid, BadSessionHybridSettingIsOneLineNamingTheFile) {
  std::ofstream(dir / "bad.json") << R"({"cpr": {"hybrid": true, "colouring": "purple"}})";
  const auto run = runAngioray(gui(" --session " + file("bad.json") + " --screenshot " + file("x.png")));
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("bad.json"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("colouring"), std::string::npos) << run.output;
  std::ofstream(dir / "far.json") << R"({"cpr": {"transition_mm": -1}})";
  EXPECT_NE(
      runAngioray(gui(" --session " + file("far.json") + " --screenshot " + file("x.png"))).exitCode, 0);
}

}  // namespace
