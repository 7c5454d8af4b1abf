// Sessions keep the VesselGlyph panel (centerline file, shapes, outside, cleft, half vessel, focus
// and context TFs) through the headless twin: a session saved with VesselGlyph and the hybrid on
// and non-default settings, reopened in another process from the session alone, shows the same
// settings and the same image; a session whose centerline file is gone or broken still opens
// (dataset, view, TF) with the error in the VesselGlyph panel and VesselGlyph off.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/phantom_folder_test.h"
#include "tests/support/run_angioray.h"
#include "tests/support/widget_points.h"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using angio::test_support::runAngioray;

// Tall enough for the side panel down to the Session section without scrolling.
const std::string kWindow = " --size 1000x1800 --timeout 120";

using angio::test_support::across;
using angio::test_support::leftEnd;

class GuiSessionVessel : public angio::test_support::PhantomFolderTest {
 protected:
  const char* folderPrefix() const override { return "gui-session-vessel"; }

  std::string gui(const std::string& extra) const { return "gui --headless" + kWindow + extra; }
  std::string onPhantom(const std::string& extra) const {
    std::string arguments = file("phantom.nrrd");  // (appended piecewise: GCC 12's -Wrestrict misfires)
    arguments += " --centerlines " + file("phantom.csv");
    arguments += extra;
    return gui(" " + arguments);
  }
  angio::test_support::ProgramRun runScript(const std::string& name, const std::string& steps,
                                            const std::string& extra) {
    std::ofstream(dir / name) << steps;
    return runAngioray(onPhantom(extra + " --script " + file(name)));
  }
  Json startLayout() {
    const auto run = runAngioray(onPhantom(" --state-out " + file("start.json")));
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return readJson("start.json")["runtime"]["layout"];
  }
  std::string saveSessionSteps(const Json& layout, const std::string& name) const {
    return R"({"click": )" + across(layout["session_path"], 0.5f) +
           R"(}, {"key": "Ctrl+A"}, {"text": ")" + file(name) + R"("}, {"key": "Enter"}, {"click": )" +
           across(layout["session_save"], 0.5f) + R"(}, {"wait_ms": 50})";
  }
};

// Clicks that move the VesselGlyph panel away from every default, bottom-up so that no click moves
// a later one's widget (the context's sliders change rows below them), then edit the focus TF.
std::string vesselSteps(const Json& layout) {
  std::string steps;
  for (const char* name : {"cpr_hybrid", "vg_half_vessel", "vg_cleft", "vg_outside_main", "vg_overlay",
                           "vg_context_tube", "vg_focus_mm"}) {
    EXPECT_TRUE(layout.contains(name)) << name;
    steps += R"({"click": )" + leftEnd(layout[name]) + "}, ";
  }
  steps += R"({"click": )" + across(layout["vg_focus_radius"], 0.3f) + "}, ";
  steps += R"({"click": )" + leftEnd(layout["vg_edit_focus"]) + R"(}, {"wait_ms": 50}, )";
  steps += R"({"double_click": )" + across(layout["tf_plot"], 0.5f) + R"(}, {"move": [5, 5]}, )";
  steps += R"({"click": )" + leftEnd(layout["vg_edit_main"]) +
           R"(}, {"move": [5, 5]}, {"wait_level": "high"})";
  return steps;
}

TEST_F(GuiSessionVessel, SavedVesselGlyphSessionReopensWithTheSameSettingsAndImage) {
  const Json start = startLayout();
  // Where the Session section's widgets are once the panel has changed (one run to find out).
  auto run =
      runScript("probe.json",
                "[" + vesselSteps(start) + R"(, {"state": ")" + file("probe-state.json") + "\"}]", "");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json changedLayout = readJson("probe-state.json")["runtime"]["layout"];

  run = runScript("save.json",
                  "[" + vesselSteps(start) + R"(, {"state": ")" + file("before.json") + "\"}, " +
                      saveSessionSteps(changedLayout, "vg-session.json") + "]",
                  "");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json before = readJson("before.json");
  const Json& vg = before["runtime"]["vessel_glyph"];
  // The first process really is away from the defaults.
  EXPECT_TRUE(vg["enabled"].get<bool>()) << vg;
  EXPECT_TRUE(vg["rendering"].get<bool>()) << vg;
  EXPECT_TRUE(vg["hybrid"]["rendering"].get<bool>()) << vg;
  EXPECT_FALSE(vg["overlay"].get<bool>());
  EXPECT_TRUE(vg["cleft"].get<bool>());
  EXPECT_TRUE(vg["half_vessel"].get<bool>());
  EXPECT_EQ(vg["outside"], "main-tf");
  EXPECT_EQ(vg["context"].get<std::string>().rfind("tube:", 0), 0u) << vg["context"];
  const std::string focus = vg["focus"];
  EXPECT_NE(focus.find("mm"), std::string::npos) << focus;
  EXPECT_NE(focus, "circle:radius=5mm");     // the slider moved it off the mm button's default
  EXPECT_NE(vg["focus_tf"], "cta-vessels");  // edited
  EXPECT_EQ(vg["tf_editing"], "main");
  EXPECT_EQ(before["runtime"]["shown"]["level"], "high");

  // The file: the section with the centerline file and the TFs in full.
  const Json saved = readJson("vg-session.json");
  ASSERT_TRUE(saved["vessel_glyph"].is_object()) << saved;
  EXPECT_EQ(saved["vessel_glyph"]["centerlines"], file("phantom.csv"));
  EXPECT_EQ(saved["vessel_glyph"]["centerlines_absolute"],
            fs::path(file("phantom.csv")).lexically_normal().string());
  EXPECT_EQ(saved["vessel_glyph"]["focus_tf"], before["state"]["vessel_glyph"]["focus_tf"]);
  EXPECT_EQ(saved["vessel_glyph"]["context"]["shape"], "tube");
  EXPECT_TRUE(saved["cpr"]["hybrid"].get<bool>());

  // Another process from the session alone (no VOLUME, no --centerlines).
  run = runAngioray(
      gui(" --session " + file("vg-session.json") + " --state-out " + file("reopened.json")));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json reopened = readJson("reopened.json");
  const Json& again = reopened["runtime"]["vessel_glyph"];
  for (const char* key : {"enabled", "rendering", "overlay", "centerlines", "paths", "focus", "context",
                          "outside", "cleft", "half_vessel", "focus_tf", "context_tf", "error"})
    EXPECT_EQ(again[key], vg[key]) << key;
  EXPECT_EQ(again["hybrid"], vg["hybrid"]);
  EXPECT_EQ(reopened["state"]["vessel_glyph"], before["state"]["vessel_glyph"]);
  EXPECT_EQ(reopened["state"]["view"], before["state"]["view"]);
  EXPECT_EQ(reopened["state"]["levels"], before["state"]["levels"]);
  EXPECT_EQ(reopened["runtime"]["shown"]["level"], "high");
  EXPECT_EQ(reopened["runtime"]["shown"]["checksum"], before["runtime"]["shown"]["checksum"]);
}

TEST_F(GuiSessionVessel, SessionWithAMissingOrBrokenCenterlineFileOpensWithTheErrorAndVesselGlyphOff) {
  const auto save = runScript("save.json", "[" + saveSessionSteps(startLayout(), "base.json") + "]", "");
  ASSERT_EQ(save.exitCode, 0) << save.output;
  std::ofstream(dir / "broken.csv") << "path,x_mm,y_mm,z_mm,radius_mm\n0,1,2,nan,1\n0,1,2\n";
  for (const std::string name : {"gone.csv", "broken.csv"}) {
    Json session = readJson("base.json");
    session["view"]["angle_deg"] = 30;
    session["vessel_glyph"].update(Json{{"centerlines", name},
                                        {"centerlines_absolute", file(name)},
                                        {"enabled", true},
                                        {"cleft", true}});
    std::ofstream(dir / "in.json") << session.dump();
    const auto run =
        runAngioray(gui(" --session " + file("in.json") + " --state-out " + file("open.json")));
    ASSERT_EQ(run.exitCode, 0) << name << ": " << run.output;
    const Json state = readJson("open.json");
    const Json& vg = state["runtime"]["vessel_glyph"];
    const std::string error = vg["error"];
    EXPECT_NE(error.find(name), std::string::npos) << vg;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_FALSE(vg["enabled"].get<bool>()) << vg;
    EXPECT_FALSE(vg["rendering"].get<bool>()) << vg;
    EXPECT_EQ(vg["paths"], 0);
    EXPECT_TRUE(vg["cleft"].get<bool>());  // the rest of the section is applied
    // The session's dataset, view and TF are open, rendered to the high level.
    EXPECT_EQ(state["runtime"]["dataset"]["name"], session["dataset"]);
    EXPECT_DOUBLE_EQ(state["state"]["view"]["angle_deg"].get<double>(), 30);
    EXPECT_EQ(state["state"]["transfer_function"], session["transfer_function"]);
    EXPECT_EQ(state["runtime"]["shown"]["level"], "high");
    EXPECT_DOUBLE_EQ(state["runtime"]["shown"]["angle_deg"].get<double>(), 30);
  }
}

}  // namespace
