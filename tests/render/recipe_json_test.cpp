// Render sidecars (io/render_sidecar.h): every field survives save + load exactly, and broken
// sidecars give one-line errors naming the file and the key.
#include "render/recipe_json.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "io/input_error.h"
#include "tests/support/replaced_once.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

namespace fs = std::filesystem;

TransferFunction tf(const std::string& name, double shift) {
  TransferFunction t;
  t.name = name;
  t.points = {{-1024, {0.f, 0.f, 0.f}, 0.0},
              {150.25 + shift, {0.6f, 0.1f, 0.05f}, 0.0},
              {300 + shift, {0.9f, 0.3f, 1.f / 3.f}, 0.4 + 1e-12}};
  t.modulators = {0.75, -12.5};
  t.mipWindow = 777.125;
  t.mipLevel = 1.0 / 3.0;
  return t;
}

// Every field set to something other than its default; numbers that are not short decimals.
RenderRecipe everything() {
  RenderRecipe s;
  s.image = "/data/out image.png";
  s.dataset = "/data/ä aorta.mha";
  s.labels = "/data/labels.nrrd";
  s.quality = Quality::medium;
  s.raycaster = Raycaster::reference;
  s.params.axis = Axis::j;
  s.params.angleDeg = 1.0 / 7.0;
  s.params.sampling = {0.3 + 1e-15, 0.7, Filter::mean, 0.995};
  s.params.shading = {false, 0.123456789012345, 0.9};
  s.params.compositing = Compositing::dvr;
  s.params.mip = {1234.5, -17.25};
  s.tf = tf("plain", 0);
  VesselGlyphRecipe vg;
  vg.centerlines = "/data/aorta-centerlines.vtp";
  vg.settings.focus = {RadiusMode::constant, 3.3, 0.25};
  vg.settings.context = ContextShape::tube;
  vg.settings.slab = {1.5, 2.5, std::numeric_limits<double>::infinity()};
  vg.settings.contextTube = {RadiusMode::vesselFactor, 4.5, 0.5};
  vg.settings.cleft = true;
  vg.settings.halfVessel = true;
  vg.settings.unknownVesselRadiusMm = 2.75;
  vg.settings.simplifyToleranceMm = 0.01;
  vg.focusTf = tf("focus", 10);
  vg.contextTf = tf("context", 20);
  vg.outsideTf = tf("outside", 30);
  s.vesselGlyph = vg;
  s.hybrid = HybridCprRecipe{"2", 3.75, WindowLevel{800.5, 250.25}};
  return s;
}

void expectSame(const TransferFunction& a, const TransferFunction& b) {
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t n = 0; n < a.points.size(); ++n) {
    EXPECT_EQ(a.points[n].hu, b.points[n].hu);
    EXPECT_EQ(a.points[n].color, b.points[n].color);
    EXPECT_EQ(a.points[n].opacity, b.points[n].opacity);
  }
  EXPECT_EQ(a.modulators.opacityScale, b.modulators.opacityScale);
  EXPECT_EQ(a.modulators.huShift, b.modulators.huShift);
  EXPECT_EQ(a.mipWindow, b.mipWindow);
  EXPECT_EQ(a.mipLevel, b.mipLevel);
}

void expectSame(const TubeRadius& a, const TubeRadius& b) {
  EXPECT_EQ(a.mode, b.mode);
  EXPECT_EQ(a.value, b.value);
  EXPECT_EQ(a.marginMm, b.marginMm);
}

class RenderSidecarFiles : public test_support::TempFolderTest {
 protected:
  // The one-line message of loading `file` (empty if it loads).
  static std::string loadError(const fs::path& file) {
    try {
      loadRenderSidecar(file);
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  }
};

TEST_F(RenderSidecarFiles, EveryFieldSurvivesSaveAndLoadExactly) {
  const RenderRecipe s = everything();
  const fs::path file = dir_ / "out.png.json";
  saveRenderSidecar(s, file);
  const RenderRecipe r = loadRenderSidecar(file);
  EXPECT_EQ(r.image, s.image);
  EXPECT_EQ(r.dataset, s.dataset);
  EXPECT_EQ(r.labels, s.labels);
  EXPECT_EQ(r.quality, s.quality);
  EXPECT_EQ(r.raycaster, s.raycaster);
  EXPECT_EQ(r.params.axis, s.params.axis);
  EXPECT_EQ(r.params.angleDeg, s.params.angleDeg);
  EXPECT_EQ(r.params.sampling.isd, s.params.sampling.isd);
  EXPECT_EQ(r.params.sampling.osd, s.params.sampling.osd);
  EXPECT_EQ(r.params.sampling.filter, s.params.sampling.filter);
  EXPECT_EQ(r.params.sampling.ert, s.params.sampling.ert);
  EXPECT_EQ(r.params.shading.enabled, s.params.shading.enabled);
  EXPECT_EQ(r.params.shading.ka, s.params.shading.ka);
  EXPECT_EQ(r.params.shading.kd, s.params.shading.kd);
  EXPECT_EQ(r.params.compositing, s.params.compositing);
  EXPECT_EQ(r.params.mip.window, s.params.mip.window);
  EXPECT_EQ(r.params.mip.level, s.params.mip.level);
  expectSame(r.tf, s.tf);
  ASSERT_TRUE(r.vesselGlyph);
  const VesselGlyphRecipe &a = *r.vesselGlyph, &b = *s.vesselGlyph;
  EXPECT_EQ(a.centerlines, b.centerlines);
  expectSame(a.settings.focus, b.settings.focus);
  EXPECT_EQ(a.settings.context, b.settings.context);
  EXPECT_EQ(a.settings.slab.frontMm, b.settings.slab.frontMm);
  EXPECT_EQ(a.settings.slab.backMm, b.settings.slab.backMm);
  EXPECT_TRUE(std::isinf(a.settings.slab.halfWidthMm));
  expectSame(a.settings.contextTube, b.settings.contextTube);
  EXPECT_EQ(a.settings.cleft, b.settings.cleft);
  EXPECT_EQ(a.settings.halfVessel, b.settings.halfVessel);
  EXPECT_EQ(a.settings.unknownVesselRadiusMm, b.settings.unknownVesselRadiusMm);
  EXPECT_EQ(a.settings.simplifyToleranceMm, b.settings.simplifyToleranceMm);
  expectSame(a.focusTf, b.focusTf);
  expectSame(a.contextTf, b.contextTf);
  ASSERT_TRUE(a.outsideTf);
  expectSame(*a.outsideTf, *b.outsideTf);
  ASSERT_TRUE(r.hybrid);
  EXPECT_EQ(r.hybrid->path, "2");
  EXPECT_EQ(r.hybrid->transitionMm, 3.75);
  ASSERT_TRUE(r.hybrid->grey);
  EXPECT_EQ(r.hybrid->grey->window, 800.5);
  EXPECT_EQ(r.hybrid->grey->level, 250.25);
}

TEST_F(RenderSidecarFiles, PlainRenderHasNoVesselGlyphAndSavingReplacesAtomically) {
  RenderRecipe s;
  s.dataset = "/data/p.mha";
  s.tf = tf("plain", 0);
  const fs::path file = dir_ / "p.png.json";
  write("p.png.json", "old");
  saveRenderSidecar(s, file);
  const RenderRecipe r = loadRenderSidecar(file);
  EXPECT_FALSE(r.vesselGlyph);
  EXPECT_FALSE(r.hybrid);
  EXPECT_FALSE(r.quality);
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().filename(), "p.png.json") << "left behind: " << entry.path();
}

TEST_F(RenderSidecarFiles, AnImageWindowSurvivesAndABrokenOneIsNamed) {
  RenderRecipe s;
  s.dataset = "/data/p.mha";
  s.tf = tf("plain", 0);
  s.params.window = ImageWindow{-12.5, 30.25, -4, 17.125};
  const fs::path file = dir_ / "w.png.json";
  saveRenderSidecar(s, file);
  EXPECT_EQ(loadRenderSidecar(file).params.window, s.params.window);
  s.params.window.reset();  // the whole image: no key at all, as before windows existed
  EXPECT_EQ(renderSidecarJson(s).find("left_mm"), std::string::npos);
  s.params.window = ImageWindow{-12.5, 30.25, -4, 17.125};
  const std::string text =
      test_support::replacedOnce(renderSidecarJson(s), "\"right_mm\": 30.25", "\"right_mm\": -20");
  const std::string message = loadError(write("inverted.json", text));
  EXPECT_NE(message.find("view.window"), std::string::npos) << message;
  EXPECT_NE(message.find("left < right"), std::string::npos) << message;
}

TEST_F(RenderSidecarFiles, SidecarPathIsTheImagePlusJson) {
  EXPECT_EQ(sidecarPathFor("/a/b.png"), fs::path("/a/b.png.json"));
  EXPECT_EQ(sidecarPathFor("c.nii.exr"), fs::path("c.nii.exr.json"));
}

TEST_F(RenderSidecarFiles, BrokenSidecarsGiveOneLineNamingTheFileAndKey) {
  const std::string good = renderSidecarJson(everything());
  auto replaced = [&](const std::string& from, const std::string& to) {
    return test_support::replacedOnce(good, from, to);
  };
  struct Case {
    std::string name, text, mention;
  };
  const Case cases[] = {
      {"truncated.json", good.substr(0, good.size() / 2), "not valid JSON"},
      {"binary.json", std::string("\x89PNG\r\n\x1a\n\0\0", 10), "not valid JSON"},
      {"array.json", "[1, 2]", "not an angioray render sidecar"},
      {"tf.json", R"({"name": "x", "points": []})", "not an angioray render sidecar"},
      {"version.json", replaced("\"angioray_render_sidecar\": 1", "\"angioray_render_sidecar\": 7"),
       "version"},
      {"axis.json", replaced("\"axis\": \"j\"", "\"axis\": \"q\""), "view.axis"},
      {"isd.json", replaced("\"isd\": ", "\"isd\": \"x\", \"was\": "), "sampling.isd"},
      {"no-dataset.json", replaced("\"dataset\"", "\"dataset_\""), "dataset"},
      {"raycaster.json", replaced("\"reference\"", "\"gpu\""), "raycaster"},
      {"cleft.json", replaced("\"cleft\": true", "\"cleft\": 1"), "vessel_glyph.cleft"},
      {"radius.json", replaced("\"radius_mode\": \"mm\"", "\"radius_mode\": \"inch\""),
       "vessel_glyph.focus.radius_mode"},
      {"tf-points.json", replaced("\"opacity\": 0.0", "\"opacity\": 2.0"), "tf"},
      {"display.json", replaced("\"grey\"", "\"rainbow\""), "hybrid_cpr.display"},
      {"hybrid-alone.json", replaced("\"vessel_glyph\": {", "\"vessel_glyph\": null, \"x\": {"),
       "needs"},
      // A hostile osd (10^10 samples per ray) and a file nested past any of ours.
      {"osd.json", replaced("\"osd\": ", "\"osd\": 1e-9, \"was\": "), "at least 0.001 voxel"},
      {"ert.json", replaced("\"ert\": ", "\"ert\": 5, \"was\": "), "ert must be in [0, 1]"},
      {"deep.json", std::string(200000, '[') + std::string(200000, ']'), "nested 200000 levels"},
  };
  EXPECT_NE(loadError(dir_ / "absent.json").find("absent.json: no such render sidecar"),
            std::string::npos);
  for (const Case& c : cases) {
    const std::string message = loadError(write(c.name, c.text));
    EXPECT_EQ(message.rfind((dir_ / c.name).string() + ": ", 0), 0u) << c.name << ": " << message;
    EXPECT_NE(message.find(c.mention), std::string::npos) << c.name << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << c.name << ": " << message;
  }
}

TEST_F(RenderSidecarFiles, MetadataRecordsTheVesselGlyphAndHybridSettings) {
  const ImageMetadata metadata = renderSidecarMetadata(everything());
  EXPECT_EQ(metadata.at("vg_focus"), "circle:radius=3.3mm");
  EXPECT_EQ(metadata.at("vg_context"), "tube:radius=4.5x");
  EXPECT_EQ(metadata.at("vg_outside"), "tf outside");
  EXPECT_EQ(metadata.at("vg_cleft"), "on");
  EXPECT_EQ(metadata.at("focus_tf"), "focus");
  EXPECT_EQ(metadata.at("context_tf"), "context");
  EXPECT_EQ(metadata.at("centerlines"), "/data/aorta-centerlines.vtp");
  EXPECT_EQ(metadata.at("hybrid_cpr_path"), "2");
  EXPECT_EQ(metadata.at("hybrid_transition_mm"), "3.75");
  EXPECT_EQ(metadata.at("dataset"), "/data/ä aorta.mha");
}

}  // namespace
}  // namespace angio
