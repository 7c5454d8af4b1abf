// The Vessels section end to end in the headless app on a 256x256x600 phantom: the Trace tool
// turns two clicks (on the aorta, on a leg artery) into a path along the phantom's ground truth;
// undo and redo step through it; a click on air changes nothing and says why; a session keeps
// the path; VesselGlyph renders it at once; an export with it unsaved writes it beside itself and
// `render --params` gives the same bytes; a new dataset drops it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <glm/glm.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_angioray.h"
#include "tests/support/widget_points.h"

namespace angio {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using test_support::runAngioray;

// Tall enough for the side panel down to the Export section with the Vessels section open.
const std::string kWindow = " --size 1200x2000 --timeout 120";

using test_support::leftEnd;
using test_support::middleOf;

std::string mmText(const glm::dvec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "[%.3f, %.3f, %.3f]", p.x, p.y, p.z);
  return text;
}

// The ground truth's paths (physical mm) from the phantom's CSV, in the order they first appear.
std::vector<std::vector<glm::dvec3>> readTruth(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::string> names;
  std::vector<std::vector<glm::dvec3>> paths;
  while (std::getline(in, line)) {
    const std::size_t comma = line.find(',');
    const std::string name = line.substr(0, comma);
    std::string numbers = line.substr(comma + 1);
    std::replace(numbers.begin(), numbers.end(), ',', ' ');
    std::istringstream row(numbers);
    glm::dvec3 p;
    row >> p.x >> p.y >> p.z;
    const auto known = std::find(names.begin(), names.end(), name);
    if (known == names.end()) {
      names.push_back(name);
      paths.emplace_back();
    }
    paths[std::size_t(std::find(names.begin(), names.end(), name) - names.begin())].push_back(p);
  }
  return paths;
}

double distanceTo(const std::vector<glm::dvec3>& path, const glm::dvec3& p) {
  double best = 1e30;
  for (const glm::dvec3& q : path) best = std::min(best, glm::distance(p, q));
  return best;
}

// What the suite shares (made once: the phantom takes seconds): the folder, the phantom and its
// truth, the steps that open the section and turn the tool on, and the state after the trace.
struct VesselsSuite {
  fs::path dir;
  std::vector<std::vector<glm::dvec3>> truth;
  glm::dvec3 aorta{0.0}, leg{0.0};
  std::string openTool;  // script steps
  Json traced;           // the state after clicks on the aorta and the leg
  Json selected;         // ... and a click on its second control point
};

class GuiVessels : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    suite_ = new VesselsSuite;
    suite_->dir = fs::temp_directory_path() / ("angioray-gui-vessels-" + std::to_string(getpid()));
    fs::remove_all(suite_->dir);
    fs::create_directories(suite_->dir);
    const auto made =
        runAngioray("phantom " + at("phantom.nrrd") +
                    " --size 256x256x600 --style simple --centerlines " + at("phantom.csv"));
    ASSERT_EQ(made.exitCode, 0) << made.output;
    suite_->truth = readTruth(suite_->dir / "phantom.csv");
    ASSERT_GE(suite_->truth.size(), 1u);
    const std::vector<glm::dvec3>& left = suite_->truth[0];
    suite_->aorta = left[100];            // 100 mm below the top
    suite_->leg = left[left.size() / 2];  // the left leg's artery, about the knee
    const Json closed = suiteState(R"({"wait_level": "high"})", "closed.json")["runtime"]["layout"];
    const std::string open = R"({"wait_level": "high"}, {"click": )" +
                             middleOf(closed["section_Vessels"]) + R"(}, {"wait_ms": 100})";
    const Json opened = suiteState(open, "open.json")["runtime"]["layout"];
    suite_->openTool =
        open + R"(, {"click": )" + leftEnd(opened["vessels_trace_tool"]) + R"(}, {"wait_ms": 50})";
    suite_->traced = suiteState(traceSteps(), "traced.json");
    suite_->selected = suiteState(traceSteps() + ", " + selectSecond(), "selected.json");
  }
  static void TearDownTestSuite() {
    fs::remove_all(suite_->dir);
    delete suite_;
  }
  static std::string at(const std::string& name) { return (suite_->dir / name).string(); }
  static test_support::ProgramRun runIn(const fs::path& folder, const std::string& steps,
                                        const std::string& extra = "") {
    std::ofstream(folder / "script.json") << steps;
    return runAngioray("gui " + at("phantom.nrrd") + " --headless" + kWindow + extra + " --script " +
                       (folder / "script.json").string());
  }
  static Json stateIn(const fs::path& folder, const std::string& steps, const std::string& name) {
    const auto result =
        runIn(folder, "[" + steps + R"(, {"state": ")" + (folder / name).string() + R"("}])");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    std::ifstream in(folder / name);
    return Json::parse(in);
  }
  static Json suiteState(const std::string& steps, const std::string& name) {
    return stateIn(suite_->dir, steps, name);
  }
  static std::string clickAt(const glm::dvec3& p) {
    return R"({"click_mm": )" + mmText(p) + R"(}, {"wait_ms": 50}, {"wait_level": "high"})";
  }
  static std::string selectSecond() {
    return R"({"click": )" + middleOf(suite_->traced["runtime"]["layout"]["vessels_point_1"]) +
           R"(}, {"wait_ms": 50})";
  }
  // The tool on, a click on the aorta and one on the leg: one path.
  static std::string traceSteps() {
    return suite_->openTool + ", " + clickAt(suite_->aorta) + ", " + clickAt(suite_->leg);
  }

  void SetUp() override {
    dir = suite_->dir / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(dir);
  }
  std::string file(const std::string& name) const { return (dir / name).string(); }
  Json readJson(const std::string& name) const {
    std::ifstream in(dir / name);
    return Json::parse(in);
  }
  Json state(const std::string& steps, const std::string& name) { return stateIn(dir, steps, name); }
  // A state step in the middle of a script.
  std::string stateStep(const std::string& name) const {
    return R"({"state": ")" + file(name) + R"("})";
  }

  static VesselsSuite* suite_;
  fs::path dir;
};
VesselsSuite* GuiVessels::suite_ = nullptr;

TEST_F(GuiVessels, TwoClicksTraceAPathAlongTheTruthAndUndoAndRedoStepThroughIt) {
  const Json& after = suite_->traced;
  const std::vector<glm::dvec3>& truth = suite_->truth[0];
  const Json& paths = after["state"]["vessels"]["paths"];
  ASSERT_EQ(paths.size(), 1u) << after["runtime"]["vessels"];
  ASSERT_EQ(paths[0]["control_points_mm"].size(), 2u);
  const Json& points = paths[0]["points"];
  ASSERT_GT(points.size(), 500u);  // 0.5 mm apart over ~500 mm
  double sum = 0, worst = 0;
  for (const Json& p : points) {
    const double d = distanceTo(truth, {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()});
    sum += d;
    worst = std::max(worst, d);
  }
  EXPECT_LT(sum / double(points.size()), 1.0);
  EXPECT_LT(worst, 3.0);
  const Json& report = after["runtime"]["vessels"];
  EXPECT_EQ(report["paths"][0]["points"], points.size());
  EXPECT_GT(report["paths"][0]["length_mm"].get<double>(), 400);
  EXPECT_TRUE(report["unsaved"].get<bool>());
  EXPECT_EQ(report["undo"], 2);  // a step per click

  // Undo twice (the button, then Ctrl+Z while the section has the focus): no path; redo both
  // (Ctrl+Shift+Z: the Redo button has moved up with the path list gone).
  const Json& layout = after["runtime"]["layout"];
  const std::string redo = R"({"key": "Ctrl+Shift+Z"}, {"wait_ms": 50})";
  const auto run = runIn(dir, "[" + traceSteps() + R"(, {"click": )" + middleOf(layout["vessels_undo"]) +
                                  R"(}, {"wait_ms": 50}, {"key": "Ctrl+Z"}, {"wait_ms": 50}, )" +
                                  stateStep("undone.json") + ", " + redo + ", " + redo + ", " +
                                  stateStep("redone.json") + "]");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json undone = readJson("undone.json");
  EXPECT_TRUE(undone["state"]["vessels"]["paths"].empty()) << undone["runtime"]["vessels"];
  EXPECT_EQ(undone["runtime"]["vessels"]["redo"], 2);
  const Json redone = readJson("redone.json");
  EXPECT_TRUE(redone["state"]["vessels"]["paths"] == paths) << redone["runtime"]["vessels"];
  EXPECT_EQ(redone["runtime"]["vessels"]["undo"], 2);
}

TEST_F(GuiVessels, AMovedPointIsSnappedAndThePathTracedAgainADeletedOneLeavesTheOther) {
  const glm::dvec3 lower = suite_->truth[0][suite_->truth[0].size() * 3 / 4];  // below the knee
  // "move" and "Delete point" show once a point is selected.
  const Json& rows = suite_->selected["runtime"]["layout"];
  const auto run = runIn(
      dir, "[" + traceSteps() + ", " + selectSecond() + R"(, {"click": )" +
               leftEnd(rows["vessels_move_point"]) + R"(}, {"wait_ms": 50}, )" + clickAt(lower) + ", " +
               stateStep("moved.json") + ", " + selectSecond() + R"(, {"click": )" +
               middleOf(rows["vessels_delete_point"]) +
               R"(}, {"wait_ms": 50}, {"wait_level": "high"}, )" + stateStep("deleted.json") + "]");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json& before = suite_->traced["state"]["vessels"]["paths"][0];
  const Json moved = readJson("moved.json")["state"]["vessels"]["paths"];
  ASSERT_EQ(moved.size(), 1u);
  ASSERT_EQ(moved[0]["control_points_mm"].size(), 2u);
  EXPECT_EQ(moved[0]["control_points_mm"][0], before["control_points_mm"][0]);
  const Json& p = moved[0]["control_points_mm"][1];
  EXPECT_LT(glm::distance(glm::dvec3(p[0].get<double>(), p[1].get<double>(), p[2].get<double>()), lower),
            8.0)
      << p;                                                       // snapped near the click
  EXPECT_GT(moved[0]["points"].size(), before["points"].size());  // a longer path
  const Json deleted = readJson("deleted.json")["state"]["vessels"]["paths"];
  ASSERT_EQ(deleted.size(), 1u);
  EXPECT_EQ(deleted[0]["control_points_mm"].size(), 1u);
  EXPECT_TRUE(deleted[0]["points"].empty());  // one point: nothing to trace
}

TEST_F(GuiVessels, AClickOnAirChangesNothingAndSaysWhy) {
  // Beside the legs, at the knee's height: nothing along the ray.
  const Json after = state(suite_->openTool + ", " + clickAt({-200, 0, suite_->leg.z}), "air.json");
  const Json& report = after["runtime"]["vessels"];
  EXPECT_TRUE(after["state"]["vessels"]["paths"].empty());
  EXPECT_EQ(report["undo"], 0);
  EXPECT_FALSE(report["problem"].get<std::string>().empty()) << report;
}

TEST_F(GuiVessels, ASessionKeepsTheTracedPath) {
  const Json& traced = suite_->traced;
  std::ofstream(dir / "session.json") << traced["state"].dump();
  const auto restored = runAngioray("gui --headless" + kWindow + " --session " + file("session.json") +
                                    " --state-out " + file("restored.json"));
  ASSERT_EQ(restored.exitCode, 0) << restored.output;
  const Json again = readJson("restored.json");
  EXPECT_EQ(again["state"]["vessels"]["paths"], traced["state"]["vessels"]["paths"]);
  EXPECT_TRUE(again["state"]["vessels"]["unsaved"].get<bool>());
  EXPECT_EQ(again["runtime"]["vessel_glyph"]["paths"], 1);  // VesselGlyph and the CPR have it
}

TEST_F(GuiVessels, VesselGlyphRendersTheTracedPathAndAnExportWritesItBesideItself) {
  const Json& layout = suite_->traced["runtime"]["layout"];
  const std::string vesselGlyph = traceSteps() + R"(, {"click": )" + leftEnd(layout["vg_enable"]) +
                                  R"(}, {"move": [5, 5]}, {"wait_level": "high"})";
  const std::string exportSteps = R"({"click": )" + middleOf(layout["export_path"]) +
                                  R"(}, {"key": "Ctrl+A"}, {"text": ")" + file("view.png") +
                                  R"("}, {"key": "Enter"}, {"click": )" +
                                  middleOf(layout["export_button"]) + R"(}, {"wait_level": "high"})";
  const auto run =
      runIn(dir, "[" + vesselGlyph + ", " + stateStep("on.json") + ", " + exportSteps + "]");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json on = readJson("on.json");
  const Json& vg = on["runtime"]["vessel_glyph"];
  EXPECT_TRUE(vg["rendering"].get<bool>()) << vg;
  EXPECT_EQ(vg["rendered_paths"], 1);
  ASSERT_TRUE(fs::exists(file("view.png")));
  std::ifstream sidecarFile(file("view.png.json"));
  const Json sidecar = Json::parse(sidecarFile);
  EXPECT_EQ(sidecar["vessel_glyph"]["centerlines"], file("view.png.centerlines.vtp"));
  ASSERT_TRUE(fs::exists(file("view.png.centerlines.vtp")));
  const auto again =
      runAngioray("render --params " + file("view.png.json") + " -o " + file("again.png"));
  ASSERT_EQ(again.exitCode, 0) << again.output;
  std::ifstream a(file("view.png"), std::ios::binary), b(file("again.png"), std::ios::binary);
  const std::string first((std::istreambuf_iterator<char>(a)), {}),
      second((std::istreambuf_iterator<char>(b)), {});
  EXPECT_EQ(first, second);
}

TEST_F(GuiVessels, ARotationSeriesWritesTheTracedPathIntoItsFolderAndEachViewRendersAgain) {
  const Json& layout = suite_->traced["runtime"]["layout"];
  const std::string folder = file("series");
  const std::string vesselGlyph =
      R"({"click": )" + leftEnd(layout["vg_enable"]) + R"(}, {"move": [5, 5]}, {"wait_level": "high"})";
  const std::string twoViews = R"({"click": )" + middleOf(layout["series_count"]) +
                               R"(}, {"key": "Ctrl+A"}, {"text": "2"}, {"key": "Enter"})";
  const std::string intoFolder = R"({"click": )" + middleOf(layout["series_folder"]) +
                                 R"(}, {"key": "Ctrl+A"}, {"text": ")" + folder +
                                 R"("}, {"key": "Enter"})";
  const std::string start = R"({"click": )" + middleOf(layout["series_button"]) +
                            R"(}, {"wait_ms": 100}, {"wait_level": "high"})";
  const std::string steps =
      traceSteps() + ", " + vesselGlyph + ", " + twoViews + ", " + intoFolder + ", " + start;
  const auto run = runIn(dir, "[" + steps + "]");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const fs::path beside = fs::path(folder) / "vessels.centerlines.vtp";
  ASSERT_TRUE(fs::exists(beside));
  std::ifstream sidecarFile(fs::path(folder) / "view-001.png.json");
  ASSERT_TRUE(sidecarFile) << run.output;
  EXPECT_EQ(Json::parse(sidecarFile)["vessel_glyph"]["centerlines"], beside.string());
  const auto again =
      runAngioray("render --params " + folder + "/view-001.png.json -o " + file("again.png"));
  ASSERT_EQ(again.exitCode, 0) << again.output;
  std::ifstream a(folder + "/view-001.png", std::ios::binary), b(file("again.png"), std::ios::binary);
  const std::string first((std::istreambuf_iterator<char>(a)), {}),
      second((std::istreambuf_iterator<char>(b)), {});
  EXPECT_TRUE(first == second);
}

TEST_F(GuiVessels, SavedPathsLoadBackWithTheirNamesAndAreNoLongerUnsaved) {
  const Json& layout = suite_->traced["runtime"]["layout"];
  const std::string saveAs = R"({"click": )" + middleOf(layout["vessels_path"]) +
                             R"(}, {"key": "Ctrl+A"}, {"text": ")" + file("traced.mrk.json") +
                             R"("}, {"key": "Enter"}, {"click": )" + middleOf(layout["vessels_save"]) +
                             R"(}, {"wait_ms": 50})";
  const std::string load = R"({"click": )" + middleOf(layout["vessels_load"]) +
                           R"(}, {"wait_ms": 100}, {"wait_level": "high"})";
  const auto run = runIn(dir, "[" + traceSteps() + ", " + saveAs + ", " + stateStep("saved.json") +
                                  ", " + load + ", " + stateStep("loaded.json") + "]");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  ASSERT_TRUE(fs::exists(file("traced.mrk.json")));
  const Json saved = readJson("saved.json")["state"]["vessels"];
  EXPECT_EQ(saved["file"], file("traced.mrk.json"));
  EXPECT_FALSE(saved["unsaved"].get<bool>());
  const Json loaded = readJson("loaded.json");
  const Json& paths = loaded["state"]["vessels"]["paths"];
  ASSERT_EQ(paths.size(), 1u) << loaded["runtime"]["vessels"];
  EXPECT_EQ(paths[0]["name"], "path 1");
  EXPECT_TRUE(paths[0]["control_points_mm"].empty());              // read from a file: not traced here
  EXPECT_TRUE(paths[0]["points"] == saved["paths"][0]["points"]);  // the same numbers
  EXPECT_EQ(loaded["runtime"]["vessels"]["undo"], 3);              // two clicks and the load
}

TEST_F(GuiVessels, AClickOnTheCprViewAddsTheCenterlinePointThere) {
  const Json& layout = suite_->traced["runtime"]["layout"];
  ASSERT_TRUE(layout.contains("cpr_shown")) << layout;
  const std::string showCpr =
      traceSteps() + R"(, {"click": )" + leftEnd(layout["cpr_shown"]) + R"(}, {"wait_level": "high"})";
  const Json shown = state(showCpr, "cpr-shown.json");
  ASSERT_TRUE(shown["runtime"]["layout"].contains("cpr_image")) << shown["runtime"]["layout"];
  const Json after =
      state(showCpr + R"(, {"click": )" + middleOf(shown["runtime"]["layout"]["cpr_image"]) +
                R"(}, {"wait_ms": 50}, {"wait_level": "high"})",
            "cpr-clicked.json");
  const Json& paths = after["state"]["vessels"]["paths"];
  ASSERT_EQ(paths.size(), 1u) << after["runtime"]["vessels"];
  const Json& controls = paths[0]["control_points_mm"];
  ASSERT_EQ(controls.size(), 3u) << after["runtime"]["vessels"];
  // The CPR's middle row is a point of the traced centerline, so of the truth (within a voxel).
  const Json& added = controls[2];
  const glm::dvec3 point{added[0].get<double>(), added[1].get<double>(), added[2].get<double>()};
  EXPECT_LT(distanceTo(suite_->truth[0], point), 2.0) << added;
}

TEST_F(GuiVessels, ANewDatasetDropsThePathsAndSaysSo) {
  const Json after = state(traceSteps() + R"(, {"open": ")" + at("phantom.nrrd") +
                               R"("}, {"wait_ms": 100}, {"wait_level": "high"})",
                           "reopened.json");
  EXPECT_TRUE(after["state"]["vessels"]["paths"].empty());
  EXPECT_EQ(after["runtime"]["vessel_glyph"]["paths"], 0);
  EXPECT_NE(
      after["runtime"]["message"].get<std::string>().find("dropped with the old dataset: 1 vessel path"),
      std::string::npos)
      << after["runtime"]["message"];
}

}  // namespace
}  // namespace angio
