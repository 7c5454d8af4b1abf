// Session files: a saved session loads back field for field (the VesselGlyph section too); bad
// files are one-line InputErrors naming the file and the key; the last session lives under
// XDG_CONFIG_HOME; recent files stay unique and few.
#include "gui/session_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

#include "io/input_error.h"
#include "io/tf_file.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

namespace fs = std::filesystem;

// The folder, and XDG_CONFIG_HOME restored afterwards.
class SessionFileTest : public test_support::TempFolderTest {
 protected:
  void SetUp() override {
    TempFolderTest::SetUp();
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME")) savedXdg_ = xdg;
  }
  void TearDown() override {
    if (savedXdg_) setenv("XDG_CONFIG_HOME", savedXdg_->c_str(), 1);
    else unsetenv("XDG_CONFIG_HOME");
    TempFolderTest::TearDown();
  }

  // Loading `text` must throw one line that starts with the file's name and contains `problem`.
  void expectRejected(const std::string& text, const std::string& problem) {
    SCOPED_TRACE(text);
    const fs::path file = write("bad-session.json", text);
    const auto message = test_support::expectInputError([&] { loadSession(file); }, file, problem);
    if (message) {
      EXPECT_EQ(message->rfind(file.string() + ": ", 0), 0u) << *message;
    }
  }

  std::optional<std::string> savedXdg_;
};

// Every field away from its default, so a field that is not written or not read shows.
Document unusualSession() {
  Document s;
  s.dataset = "/data/cta/aorta.mha";
  s.view = {Axis::j, 123.25, 2.5, {-40.5, 17.0}, 0.8, true, -45};
  s.tf.name = "my vessels";
  s.tf.points = {{-200, {0.1f, 0.2f, 0.3f}, 0.0}, {350, {0.9f, 0.4f, 0.25f}, 0.6}};
  s.tf.modulators = {0.75, 35};
  s.tf.mipWindow = 900;
  s.tf.mipLevel = 320;
  s.tf.labels = {{1, "bone", LabelMode::hidden, {}, {0.9f, 0.8f, 0.7f}},
                 {4, "left kidney", LabelMode::tf, {{0, {0, 1, 0}, 0.25}}, {0, 1, 0}}};
  s.labels = {"/data/cta/aorta-labels.seg.nrrd", true};
  s.tfPreset = "";
  s.mode = Compositing::mip;
  s.shading = {false, 0.45, 0.55};
  s.levels[0] = {2.0, 1.5, Filter::nearest, 0.9};
  s.levels[2] = {0.25, 0.125, Filter::mean, 1.0};
  s.levels[2].preintegrated = true;
  s.levels[1].adaptive = AdaptiveIntegration{0.005, 3.0, 0.25};
  s.levels[0].adaptiveSampling = AdaptiveSampling{2, 5, 0.07};
  s.cpr = {.shown = true,
           .mode = CprMode::projected,
           .path = 1,
           .coloring = CprColoring::focusTf,
           .window = {1200, 300},
           .widthMm = 42,
           .hybrid = true,
           .transitionMm = 3.5,
           .zoom = 2.5,
           .panPx = {-30, 12.5},
           .cursor = CprCursor{2, 87.25}};
  s.slices = {true, glm::dvec3(12.5, -3.25, 80), {2000, 500}};
  s.slices.panes[int(SliceOrientation::coronal)] = {3.5, {-12.25, 40}};
  s.panelsOpen = {{"Data", true}, {"Transfer function", false}};
  s.recentFiles = {"/data/b.nrrd", "/data/dicom/series1"};
  VesselGlyphState& vg = s.vesselGlyph;
  vg.centerlines = "cl/aorta.vtp";
  vg.centerlinesAbsolute = "/data/cta/cl/aorta.vtp";
  vg.enabled = true;
  vg.overlay = false;
  vg.settings.focus = {RadiusMode::constant, 3.25, 0.5};
  vg.settings.context = ContextShape::tube;
  vg.settings.slab = {12.5, 7.75, 33};
  vg.settings.contextTube = {RadiusMode::vesselFactor, 4.5, 1.25};
  vg.settings.cleft = true;
  vg.settings.halfVessel = true;
  vg.settings.unknownVesselRadiusMm = 1.5;
  vg.settings.simplifyToleranceMm = 0.125;
  vg.outsideRendered = true;
  vg.focusTf.name = "my focus";
  vg.focusTf.points = {{100, {1.0f, 0.1f, 0.05f}, 0.0}, {400, {1.0f, 0.9f, 0.8f}, 0.95}};
  vg.focusTf.modulators = {0.5, -20};
  vg.contextTf.name = "my context";
  vg.contextTf.points = {
      {-300, {0.3f, 0.3f, 0.3f}, 0.0}, {50, {0.8f, 0.6f, 0.5f}, 0.02}, {900, {1.0f, 1.0f, 1.0f}, 0.1}};
  vg.focusPreset = "";
  vg.contextPreset = "soft-tissue-context";
  vg.focusFollowsMain = false;
  vg.contextFollowsMain = false;
  return s;
}

void expectSameTf(const TransferFunction& a, const TransferFunction& b) {
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.points.size(), b.points.size()) << a.name;
  for (std::size_t n = 0; n < a.points.size(); ++n) {
    EXPECT_DOUBLE_EQ(a.points[n].hu, b.points[n].hu) << a.name << " point " << n;
    EXPECT_FLOAT_EQ(a.points[n].color.r, b.points[n].color.r) << a.name << " point " << n;
    EXPECT_FLOAT_EQ(a.points[n].color.g, b.points[n].color.g) << a.name << " point " << n;
    EXPECT_FLOAT_EQ(a.points[n].color.b, b.points[n].color.b) << a.name << " point " << n;
    EXPECT_DOUBLE_EQ(a.points[n].opacity, b.points[n].opacity) << a.name << " point " << n;
  }
  EXPECT_DOUBLE_EQ(a.modulators.opacityScale, b.modulators.opacityScale) << a.name;
  EXPECT_DOUBLE_EQ(a.modulators.huShift, b.modulators.huShift) << a.name;
}

void expectSameRadius(const TubeRadius& a, const TubeRadius& b, const char* what) {
  EXPECT_EQ(a.mode, b.mode) << what;
  EXPECT_DOUBLE_EQ(a.value, b.value) << what;
  EXPECT_DOUBLE_EQ(a.marginMm, b.marginMm) << what;
}

TEST_F(SessionFileTest, SavedSessionLoadsBackFieldForField) {
  const Document saved = unusualSession();
  const fs::path file = dir_ / "sub" / "session.json";  // the folder is created
  saveSession(saved, file);
  const Document loaded = loadSession(file);
  EXPECT_EQ(loaded.dataset, saved.dataset);
  EXPECT_EQ(loaded.view.axis, Axis::j);
  EXPECT_DOUBLE_EQ(loaded.view.angleDeg, 123.25);
  EXPECT_DOUBLE_EQ(loaded.view.zoom, 2.5);
  EXPECT_DOUBLE_EQ(loaded.view.panPx.x, -40.5);
  EXPECT_DOUBLE_EQ(loaded.view.panPx.y, 17.0);
  EXPECT_DOUBLE_EQ(loaded.view.degreesPerPixel, 0.8);
  EXPECT_TRUE(loaded.view.autoSpin);
  EXPECT_DOUBLE_EQ(loaded.view.spinDegreesPerSecond, -45);
  EXPECT_EQ(loaded.tf.name, "my vessels");
  ASSERT_EQ(loaded.tf.points.size(), 2u);
  EXPECT_DOUBLE_EQ(loaded.tf.points[1].hu, 350);
  EXPECT_FLOAT_EQ(loaded.tf.points[1].color.g, 0.4f);
  EXPECT_DOUBLE_EQ(loaded.tf.points[1].opacity, 0.6);
  EXPECT_DOUBLE_EQ(loaded.tf.modulators.opacityScale, 0.75);
  EXPECT_DOUBLE_EQ(loaded.tf.modulators.huShift, 35);
  EXPECT_DOUBLE_EQ(loaded.tf.mipWindow, 900);
  EXPECT_DOUBLE_EQ(loaded.tf.mipLevel, 320);
  EXPECT_EQ(loaded.tf.labels, saved.tf.labels);
  EXPECT_EQ(loaded.labels, saved.labels);
  EXPECT_EQ(loaded.mode, Compositing::mip);
  EXPECT_FALSE(loaded.shading.enabled);
  EXPECT_DOUBLE_EQ(loaded.shading.ka, 0.45);
  EXPECT_DOUBLE_EQ(loaded.shading.kd, 0.55);
  for (int q = 0; q < kQualityLevels; ++q) {
    EXPECT_DOUBLE_EQ(loaded.levels[q].isd, saved.levels[q].isd) << q;
    EXPECT_DOUBLE_EQ(loaded.levels[q].osd, saved.levels[q].osd) << q;
    EXPECT_EQ(loaded.levels[q].filter, saved.levels[q].filter) << q;
    EXPECT_EQ(loaded.levels[q].preintegrated, saved.levels[q].preintegrated) << q;
    EXPECT_EQ(loaded.levels[q].adaptive, saved.levels[q].adaptive) << q;
    EXPECT_EQ(loaded.levels[q].adaptiveSampling, saved.levels[q].adaptiveSampling) << q;
    EXPECT_DOUBLE_EQ(loaded.levels[q].ert, saved.levels[q].ert) << q;
  }
  EXPECT_TRUE(loaded.cpr.shown);
  EXPECT_EQ(loaded.cpr.mode, CprMode::projected);
  EXPECT_EQ(loaded.cpr.path, 1);
  EXPECT_EQ(loaded.cpr.coloring, CprColoring::focusTf);
  EXPECT_TRUE(loaded.cpr.hybrid);
  EXPECT_DOUBLE_EQ(loaded.cpr.transitionMm, 3.5);
  EXPECT_EQ(loaded.cpr.cursor, (CprCursor{2, 87.25}));
  EXPECT_EQ(loaded.cpr, saved.cpr);  // and the window, width, zoom and pan
  EXPECT_EQ(loaded.slices.panes[int(SliceOrientation::coronal)], (SlicePaneView{3.5, {-12.25, 40}}));
  EXPECT_EQ(loaded.slices, saved.slices);
  EXPECT_EQ(loaded.panelsOpen, saved.panelsOpen);
  EXPECT_EQ(loaded.recentFiles, saved.recentFiles);
  const VesselGlyphState &vg = loaded.vesselGlyph, &want = saved.vesselGlyph;
  EXPECT_EQ(vg.centerlines, "cl/aorta.vtp");
  EXPECT_EQ(vg.centerlinesAbsolute, "/data/cta/cl/aorta.vtp");
  EXPECT_TRUE(vg.enabled);
  EXPECT_FALSE(vg.overlay);
  expectSameRadius(vg.settings.focus, want.settings.focus, "focus");
  EXPECT_EQ(vg.settings.context, ContextShape::tube);
  EXPECT_DOUBLE_EQ(vg.settings.slab.frontMm, 12.5);
  EXPECT_DOUBLE_EQ(vg.settings.slab.backMm, 7.75);
  EXPECT_DOUBLE_EQ(vg.settings.slab.halfWidthMm, 33);
  expectSameRadius(vg.settings.contextTube, want.settings.contextTube, "context tube");
  EXPECT_TRUE(vg.settings.cleft);
  EXPECT_TRUE(vg.settings.halfVessel);
  EXPECT_DOUBLE_EQ(vg.settings.unknownVesselRadiusMm, 1.5);
  EXPECT_DOUBLE_EQ(vg.settings.simplifyToleranceMm, 0.125);
  EXPECT_TRUE(vg.outsideRendered);
  expectSameTf(vg.focusTf, want.focusTf);
  expectSameTf(vg.contextTf, want.contextTf);
  EXPECT_EQ(vg.focusPreset, "");
  EXPECT_EQ(vg.contextPreset, "soft-tissue-context");
  EXPECT_FALSE(vg.focusFollowsMain);
  EXPECT_FALSE(vg.contextFollowsMain);
  // Atomic write: nothing but the session in its folder.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "sub"), fs::directory_iterator()), 1);
}

TEST_F(SessionFileTest, MissingKeysKeepTheDefaults) {
  const Document loaded =
      loadSession(write("partial.json", R"({"dataset": "x.mha", "view": {"angle_deg": 90}})"));
  const Document defaults;
  EXPECT_EQ(loaded.dataset, "x.mha");
  EXPECT_DOUBLE_EQ(loaded.view.angleDeg, 90);
  EXPECT_EQ(loaded.view.axis, defaults.view.axis);
  EXPECT_DOUBLE_EQ(loaded.view.zoom, defaults.view.zoom);
  EXPECT_DOUBLE_EQ(loaded.levels[2].isd, defaults.levels[2].isd);
  EXPECT_FALSE(loaded.cpr.hybrid);
  EXPECT_EQ(loaded.cpr.path, -1);
  EXPECT_TRUE(loaded.vesselGlyph.centerlines.empty());
  EXPECT_FALSE(loaded.vesselGlyph.enabled);
  EXPECT_EQ(loaded.vesselGlyph.settings.context, ContextShape::slab);
  EXPECT_TRUE(loaded.vesselGlyph.focusFollowsMain);
  EXPECT_TRUE(loaded.vesselGlyph.contextFollowsMain);
}

// Sessions written before the region TFs followed the main TF name a preset or an own TF for each:
// those stay, they do not start following.
TEST_F(SessionFileTest, ARegionTfTheSessionNamesDoesNotFollowTheMainTf) {
  const Document old = loadSession(write("old.json", R"({"vessel_glyph": {"focus_tf": null,
      "focus_preset": "cta-vessels", "context_tf": null, "context_preset": "soft-tissue-context"}})"));
  EXPECT_FALSE(old.vesselGlyph.focusFollowsMain);
  EXPECT_FALSE(old.vesselGlyph.contextFollowsMain);
  EXPECT_EQ(old.vesselGlyph.contextPreset, "soft-tissue-context");
  const Document mixed = loadSession(write("mixed.json", R"({"vessel_glyph": {"focus_tf": null,
      "focus_preset": "", "context_preset": "bone", "context_follows_main_tf": true}})"));
  EXPECT_TRUE(mixed.vesselGlyph.focusFollowsMain);
  EXPECT_TRUE(mixed.vesselGlyph.contextFollowsMain);  // said so, whatever it names
}

// A hand-written session without "transfer_function": its tf_preset's TF, or the first preset as
// at start; never an empty TF (a black image).
TEST_F(SessionFileTest, ASessionThatOnlyNamesItsTfPresetGetsThatPresetsTf) {
  const Document named = loadSession(write("named.json", R"({"tf_preset": "cta-vessels"})"));
  EXPECT_EQ(named.tfPreset, "cta-vessels");
  EXPECT_EQ(named.tf, loadPresetOrFile("cta-vessels"));
  const Document unnamed = loadSession(write("unnamed.json", R"({"dataset": "x.mha"})"));
  ASSERT_FALSE(listPresets().empty());
  EXPECT_EQ(unnamed.tfPreset, listPresets().front().id);
  EXPECT_EQ(unnamed.tf, loadPresetOrFile(listPresets().front().id));
  EXPECT_FALSE(unnamed.tf.points.empty());
  expectRejected(R"({"tf_preset": "no-such-preset"})", "tf_preset 'no-such-preset' is neither");
}

TEST_F(SessionFileTest, TheCalciumColoringBringsItsWindowUnlessTheSessionGivesOne) {
  EXPECT_EQ(loadSession(write("a.json", R"({"cpr": {"colouring": "calcium"}})")).cpr.window,
            kCalciumWindow);
  EXPECT_EQ(loadSession(write("b.json", R"({"cpr": {"colouring": "calcium", "window": 500,
                                               "level": 90}})"))
                .cpr.window,
            WindowLevel(500, 90));
  EXPECT_EQ(loadSession(write("c.json", R"({"cpr": {}})")).cpr.window, kCtaLumenWindow);
}

TEST_F(SessionFileTest, VesselGlyphSectionKeepsDefaultsForMissingKeysAndTakesAnUnboundedSlab) {
  const Document loaded = loadSession(write("vg.json", R"({"vessel_glyph": {"centerlines": "c.csv",
      "context": {"half_width_mm": "inf", "back_mm": 5}, "focus": {"radius": 2.5}, "focus_tf": null}})"));
  const VesselGlyphState& vg = loaded.vesselGlyph;
  const VesselGlyphState defaults;
  EXPECT_EQ(vg.centerlines, "c.csv");
  EXPECT_TRUE(std::isinf(vg.settings.slab.halfWidthMm));
  EXPECT_DOUBLE_EQ(vg.settings.slab.backMm, 5);
  EXPECT_DOUBLE_EQ(vg.settings.slab.frontMm, defaults.settings.slab.frontMm);
  EXPECT_EQ(vg.settings.focus.mode, defaults.settings.focus.mode);
  EXPECT_DOUBLE_EQ(vg.settings.focus.value, 2.5);
  EXPECT_TRUE(vg.focusTf.points.empty());
  EXPECT_EQ(vg.overlay, defaults.overlay);
  // Written back as "inf".
  Document again = loaded;
  again.tf = unusualSession().tf;  // a session always has a main TF
  saveSession(again, dir_ / "again.json");
  EXPECT_TRUE(std::isinf(loadSession(dir_ / "again.json").vesselGlyph.settings.slab.halfWidthMm));
}

// The settings are written in the render sidecar's form (io/vessel_glyph_json.h): the same keys.
TEST_F(SessionFileTest, VesselGlyphSettingsUseTheSidecarsKeys) {
  const fs::path file = dir_ / "s.json";
  saveSession(unusualSession(), file);
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* key :
       {"\"vessel_glyph\"", "\"radius_mode\": \"mm\"", "\"radius_mode\": \"factor\"",
        "\"shape\": \"tube\"", "\"half_width_mm\"", "\"unknown_vessel_radius_mm\"",
        "\"simplify_tolerance_mm\"", "\"focus_tf\"", "\"context_tf\"", "\"outside\": \"main-tf\"",
        "\"centerlines_absolute\": \"/data/cta/cl/aorta.vtp\""})
    EXPECT_NE(text.find(key), std::string::npos) << key;
}

TEST_F(SessionFileTest, BadSessionsAreOneLineErrorsNamingTheFile) {
  expectRejected("{\"dataset\": ", "not valid JSON");
  expectRejected("[1, 2]", "a session is a JSON object");
  expectRejected(R"({"format": "something-else"})", "not an angioray session");
  expectRejected(R"({"view": {"zoom": "big"}})", "zoom is not a number");
  expectRejected(R"({"view": {"zoom": -1}})", "zoom");
  expectRejected(R"({"view": {"axis": "x"}})", "axis");
  expectRejected(R"({"mode": "xray"})", "mode");
  expectRejected(R"({"levels": {"high": {"filter": "cubic"}}})", "filter");
  expectRejected(R"({"panels": {"Data": 1}})", "panels Data");
  expectRejected(R"({"cpr": {"colouring": "purple"}})", "cpr colouring");
  expectRejected(R"({"cpr": {"mode": "curved"}})", "cpr mode");
  expectRejected(R"({"cpr": {"path": 1.5}})", "cpr path");
  expectRejected(R"({"cpr": {"path": -2}})", "path");
  expectRejected(R"({"cpr": {"transition_mm": -1}})", "transition_mm");
  expectRejected(R"({"cpr": {"hybrid": "yes"}})", "hybrid is not true or false");
  expectRejected(R"({"cpr": {"width_mm": 0}})", "width_mm");
  expectRejected(R"({"cpr": {"window": 0}})", "window");
  expectRejected(R"({"cpr": {"zoom": 1000}})", "zoom");
  expectRejected(R"({"cpr": {"pan_px": [1]}})", "cpr pan_px is not [x, y]");
  expectRejected(R"({"cpr": {"cursor": [1, 2]}})", "cpr cursor is not an object");
  expectRejected(R"({"cpr": {"cursor": {"arc_mm": 2}}})", "cpr.cursor.path is not a path index");
  expectRejected(R"({"cpr": {"cursor": {"path": 0, "arc_mm": -2}}})",
                 "cpr.cursor.arc_mm -2 is out of range");
  expectRejected(R"({"slices": {"window": 0}})", "slices.window 0 is out of range");
  expectRejected(R"({"slices": {"cursor_mm": [1, 2]}})", "slices.cursor_mm is not [x, y, z]");
  expectRejected(R"({"slices": {"shown": 1}})", "slices.shown is not true or false");
  expectRejected(R"({"slices": {"panes": {"axial": {"zoom": 0.5}}}})",
                 "slices.panes.axial.zoom 0.5 is out of range");
  expectRejected(R"({"slices": {"panes": {"sagittal": []}}})", "slices.panes.sagittal is not an object");
  expectRejected(R"({"slices": {"panes": {"coronal": {"pan_px": [1]}}}})",
                 "slices.panes.coronal pan_px is not [x, y]");
  expectRejected(R"({"transfer_function": {"name": "t", "points": [{"hu": 0}]}})", "point 1");
}

TEST_F(SessionFileTest, BadVesselGlyphValuesAreOneLineErrorsNamingTheKey) {
  const auto vg = [](const std::string& section) { return R"({"vessel_glyph": )" + section + "}"; };
  expectRejected(vg("[]"), "vessel_glyph is not an object");
  expectRejected(vg(R"({"centerlines": 3})"), "vessel_glyph.centerlines is not a string");
  expectRejected(vg(R"({"enabled": "on"})"), "vessel_glyph.enabled is not true or false");
  expectRejected(vg(R"({"overlay": 1})"), "vessel_glyph.overlay is not true or false");
  expectRejected(vg(R"({"focus": {"radius": -2}})"), "vessel_glyph.focus.radius -2 is out of range");
  expectRejected(vg(R"({"focus": {"radius": 0}})"), "vessel_glyph.focus.radius 0 is out of range");
  expectRejected(vg(R"({"focus": {"radius": "wide"}})"), "vessel_glyph.focus.radius is not a number");
  expectRejected(vg(R"({"focus": {"radius": "NaN"}})"), "vessel_glyph.focus.radius is not a number");
  expectRejected(vg(R"({"focus": {"radius": NaN}})"), "not valid JSON");
  expectRejected(vg(R"({"focus": {"radius_mode": "percent"}})"),
                 "vessel_glyph.focus.radius_mode is not factor or mm");
  expectRejected(vg(R"({"focus": {"margin_mm": -1}})"), "vessel_glyph.focus.margin_mm");
  expectRejected(vg(R"({"focus": 2})"), "vessel_glyph.focus is not an object");
  expectRejected(vg(R"({"context": {"shape": "cone"}})"),
                 "vessel_glyph.context.shape is not none, slab or tube");
  expectRejected(vg(R"({"context": {"front_mm": -5}})"),
                 "vessel_glyph.context.front_mm -5 is out of range");
  expectRejected(vg(R"({"context": {"back_mm": null}})"),
                 "vessel_glyph.context.back_mm is not a number");
  expectRejected(vg(R"({"context": {"half_width_mm": "wide"}})"), "vessel_glyph.context.half_width_mm");
  expectRejected(vg(R"({"context": {"half_width_mm": -1}})"), "vessel_glyph.context.half_width_mm");
  expectRejected(vg(R"({"context": {"tube": {"radius": -20}}})"),
                 "vessel_glyph.context.tube.radius -20 is out of range");
  expectRejected(vg(R"({"cleft": "yes"})"), "vessel_glyph.cleft is not true or false");
  expectRejected(vg(R"({"half_vessel": 0})"), "vessel_glyph.half_vessel is not true or false");
  expectRejected(vg(R"({"unknown_vessel_radius_mm": -1})"), "vessel_glyph.unknown_vessel_radius_mm");
  expectRejected(vg(R"({"simplify_tolerance_mm": "x"})"),
                 "vessel_glyph.simplify_tolerance_mm is not a number");
  expectRejected(vg(R"({"outside": "dim"})"), "vessel_glyph.outside is not clip or main-tf");
  expectRejected(vg(R"({"focus_tf": 7})"), "vessel_glyph.focus_tf is not a transfer function");
  expectRejected(vg(R"({"context_tf": {"name": "t", "points": [{"hu": 0}]}})"),
                 "vessel_glyph.context_tf: ");
  expectRejected(vg(R"({"focus_tf": null, "focus_preset": "", "focus_follows_main_tf": false})"),
                 "vessel_glyph.focus_tf is null and focus_preset empty");
}

TEST_F(SessionFileTest, MissingFileIsAnInputError) {
  EXPECT_THROW(loadSession(dir_ / "none.json"), InputError);
}

TEST_F(SessionFileTest, LastSessionLivesUnderXdgConfigHome) {
  setenv("XDG_CONFIG_HOME", dir_.c_str(), 1);
  EXPECT_EQ(lastSessionPath(), dir_ / "angioray" / "last-session.json");
  saveSession(unusualSession(), lastSessionPath());
  EXPECT_TRUE(fs::exists(dir_ / "angioray" / "last-session.json"));
}

TEST_F(SessionFileTest, RecentFilesAreUniqueNewestFirstAndAtMostTen) {
  std::vector<std::string> recent;
  for (int n = 0; n < 12; ++n) addRecentFile(recent, "/data/" + std::to_string(n) + ".mha");
  ASSERT_EQ(recent.size(), kMaxRecentFiles);
  EXPECT_EQ(recent.front(), "/data/11.mha");
  EXPECT_EQ(recent.back(), "/data/2.mha");
  addRecentFile(recent, "/data/5.mha");
  EXPECT_EQ(recent.size(), kMaxRecentFiles);
  EXPECT_EQ(recent.front(), "/data/5.mha");
  EXPECT_EQ(std::count(recent.begin(), recent.end(), "/data/5.mha"), 1);
}

TEST_F(SessionFileTest, TracedVesselPathsLoadBackExactlyAndBadOnesNameTheKey) {
  Document session;
  session.tf = unusualSession().tf;  // a session always has a main TF
  VesselPath path{"left femoral", {{1.0 / 3, -2.5, 1e-7}, {4, 5, -1156.25}}, {}};
  path.centerline = {"left femoral", {{{1.0 / 3, -2.5, 1e-7}, 2.0 / 3}, {{4, 5, -1156.25}, 1.5}}};
  session.vessels.paths = {path, {"imported", {}, {"imported", {{{0, 0, 0}, 0}, {{1, 1, 1}, 0}}}}};
  session.vessels.file = "/data/v.mrk.json";
  session.vessels.unsaved = true;
  const fs::path file = dir_ / "vessels.json";
  saveSession(session, file);
  const Document loaded = loadSession(file);
  EXPECT_EQ(loaded.vessels.paths, session.vessels.paths);
  EXPECT_EQ(loaded.vessels.file, session.vessels.file);
  EXPECT_TRUE(loaded.vessels.unsaved);
  expectRejected(
      R"({"vessels": {"paths": [{"name": "a", "control_points_mm": [[1, 2]], "points": []}]}})",
      "vessels.paths[0].control_points_mm[0] is not a list of 3 numbers");
  expectRejected(
      R"({"vessels": {"paths": [{"name": "a", "control_points_mm": [], "points": [[1, 2, 3, -1]]}]}})",
      "vessels.paths[0].points[0] has a negative radius");
}

}  // namespace
}  // namespace angio
