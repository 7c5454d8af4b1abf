// The workstation UI through its headless twin (`angioray gui --headless`): scripted input goes
// through the same ImGui code as the window, and the app's state dump and screenshots show what
// happened. Small phantom, small window, waits on quality levels rather than fixed sleeps.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "tests/support/run_angioray.h"
#include <nlohmann/json.hpp>
#include <OpenImageIO/imagebuf.h>
#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// Tall enough for the whole side panel (export section included) without scrolling.
const std::string kSmall =
    " --phantom-size 96x96x200 --phantom-style simple --size 1000x1400 --timeout 120";

using angio::test_support::runAngioray;
using GuiRun = angio::test_support::ProgramRun;

Json readJson(const fs::path& path) {
  std::ifstream in(path);
  return Json::parse(in);
}

struct Rect {
  float x0, y0, x1, y1;
  float midX() const { return (x0 + x1) / 2; }
  float midY() const { return (y0 + y1) / 2; }
};

Rect rectOf(const Json& layout) {
  return {layout[0].get<float>(), layout[1].get<float>(), layout[2].get<float>(),
          layout[3].get<float>()};
}

// Mean absolute RGB difference (0..255) over a rectangle of two same-size screenshots.
double meanDifference(const fs::path& a, const fs::path& b, const Rect& r) {
  OIIO::ImageBuf imageA(a.string()), imageB(b.string());
  EXPECT_TRUE(imageA.read() && imageB.read());
  double sum = 0;
  long count = 0;
  for (int y = int(r.y0); y < int(r.y1); ++y) {
    for (int x = int(r.x0); x < int(r.x1); ++x) {
      float pa[3], pb[3];
      imageA.getpixel(x, y, pa, 3);
      imageB.getpixel(x, y, pb, 3);
      for (int c = 0; c < 3; ++c) sum += std::abs(pa[c] - pb[c]) * 255;
      ++count;
    }
  }
  return count ? sum / double(count) : 0;
}

std::string point(float x, float y) {
  char text[64];
  std::snprintf(text, sizeof text, "[%.1f, %.1f]", x, y);
  return text;
}

class Gui : public ::testing::Test {
 protected:
  void SetUp() override {
    dir =
        fs::temp_directory_path() /
        ("angioray-gui-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
         "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir);
  }

  // Runs the headless app with `steps` (a JSON list) and returns its run; files land in dir.
  GuiRun runScript(const std::string& steps, const std::string& extra = "") {
    const fs::path script = dir / "script.json";
    std::ofstream(script) << steps;
    return runAngioray("gui --headless" + kSmall + " --script " + script.string() + " --state-out " +
                       (dir / "end.json").string() + extra);
  }

  std::string file(const std::string& name) const { return (dir / name).string(); }

  // The layout of the default start-up screen (the same for every run at this size).
  Json startupState() {
    const GuiRun run = runAngioray("gui --headless" + kSmall + " --state-out " + file("startup.json"));
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return readJson(dir / "startup.json");
  }

  fs::path dir;
};

TEST_F(Gui, HeadlessWithoutScriptShowsTheHighImageWithOrientation) {
  const GuiRun run = runAngioray("gui --headless" + kSmall + " --screenshot " + file("start.png") +
                                 " --state-out " + file("state.json"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  OIIO::ImageBuf shot(file("start.png"));
  ASSERT_TRUE(shot.read());
  EXPECT_EQ(shot.spec().width, 1000);
  EXPECT_EQ(shot.spec().height, 1400);

  const Json state = readJson(dir / "state.json");
  const Json& runtime = state["runtime"];
  EXPECT_EQ(runtime["shown"]["level"], "high");
  EXPECT_EQ(runtime["shown"]["request"], runtime["newest_request"]);
  for (const char* level : {"fast", "medium", "high"})
    EXPECT_TRUE(runtime["levels"].contains(level)) << level;
  // Axis k, angle 0: the anterior view (rendering model).
  EXPECT_EQ(runtime["orientation"]["right"], "L");
  EXPECT_EQ(runtime["orientation"]["left"], "R");
  EXPECT_EQ(runtime["orientation"]["top"], "S");
  EXPECT_EQ(runtime["orientation"]["bottom"], "I");

  // The viewport shows the image: its centre column is not all background.
  const Rect viewport = rectOf(runtime["layout"]["viewport"]);
  float brightest = 0;
  for (int y = int(viewport.y0); y < int(viewport.y1); ++y) {
    float pixel[3];
    shot.getpixel(int(viewport.midX()), y, pixel, 3);
    brightest = std::max({brightest, pixel[0], pixel[1], pixel[2]});
  }
  EXPECT_GT(brightest, 0.3f);
}

TEST_F(Gui, LeftDragRotatesAndChangesTheImage) {
  const std::string steps = R"([
    {"wait_level": "high"}, {"state": ")" +
                            file("before.json") + R"("},
    {"screenshot": ")" + file("before.png") +
                            R"("},
    {"press": [300, 300]}, {"move": [320, 300]}, {"move": [340, 300]}, {"move": [360, 300]},
    {"wait_ms": 400}, {"state": ")" +
                            file("held.json") + R"("},
    {"release": [360, 300]},
    {"wait_level": "high"},
    {"screenshot": ")" + file("after.png") +
                            R"("}])";
  const GuiRun run = runScript(steps);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json before = readJson(dir / "before.json"), held = readJson(dir / "held.json"),
             after = readJson(dir / "end.json");
  EXPECT_DOUBLE_EQ(before["state"]["view"]["angle_deg"].get<double>(), 0);
  // 60 px at 0.5 deg per pixel, grab semantics: dragging right turns theta negative.
  EXPECT_DOUBLE_EQ(held["state"]["view"]["angle_deg"].get<double>(), 330);
  // While the button is held only the fast level is rendered, however long it is held.
  EXPECT_EQ(held["runtime"]["shown"]["level"], "fast");
  EXPECT_NEAR(held["runtime"]["shown"]["angle_deg"].get<double>(), 330, 1e-9);
  EXPECT_FALSE(held["runtime"]["busy"].get<bool>());
  // Letting go continues to high.
  EXPECT_DOUBLE_EQ(after["state"]["view"]["angle_deg"].get<double>(), 330);
  EXPECT_EQ(after["runtime"]["shown"]["level"], "high");
  EXPECT_NEAR(after["runtime"]["shown"]["angle_deg"].get<double>(), 330, 1e-9);
  EXPECT_NE(after["runtime"]["shown"]["checksum"], before["runtime"]["shown"]["checksum"]);
  const Rect viewport = rectOf(after["runtime"]["layout"]["viewport"]);
  EXPECT_GT(meanDifference(dir / "before.png", dir / "after.png", viewport), 1.0);
}

// Shift+drag on the view adjusts what is seen instead of turning it: DVR, the edited TF's HU shift
// (2 HU per pixel right) and opacity modulator (up: more), one undo step for the whole drag; MIP,
// the window (4 HU per pixel right) and level (2 HU per pixel up).
TEST_F(Gui, AShiftDragOnTheViewShiftsTheTfOrMovesTheMipWindowInsteadOfTurning) {
  const std::string drag =
      R"({"drag": {"from": [300, 300], "to": [340, 280], "steps": 4, "hold": "Shift"}})";
  GuiRun run = runScript("[" + drag + R"(, {"wait_level": "fast"}])");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  Json end = readJson(dir / "end.json");
  EXPECT_DOUBLE_EQ(end["state"]["view"]["angle_deg"].get<double>(), 0);
  const Json& modulators = end["state"]["transfer_function"]["modulators"];
  EXPECT_DOUBLE_EQ(modulators["hu_shift"].get<double>(), 80);
  EXPECT_NEAR(modulators["opacity_scale"].get<double>(), std::exp(0.2), 1e-9);
  EXPECT_TRUE(end["runtime"]["tf_undo_available"].get<bool>());
  run = runScript("[" + drag + R"(, {"key": "Ctrl+Z"}, {"wait_level": "fast"}])");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  end = readJson(dir / "end.json");
  EXPECT_DOUBLE_EQ(end["state"]["transfer_function"]["modulators"]["hu_shift"].get<double>(), 0);
  EXPECT_FALSE(end["runtime"]["tf_undo_available"].get<bool>());  // the drag was one step

  run = runScript("[" + drag + R"(, {"wait_level": "fast"}])", " --mip");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json mip = readJson(dir / "end.json")["state"]["transfer_function"]["mip"];
  const Json start = startupState()["state"]["transfer_function"]["mip"];
  EXPECT_DOUBLE_EQ(mip["window"].get<double>(), start["window"].get<double>() + 160);
  EXPECT_DOUBLE_EQ(mip["level"].get<double>(), start["level"].get<double>() + 40);
}

// The drag's first level fits the motion budget (render/motion_sampling.h): with a budget the
// small phantom's fast frame is far within, the drag renders at the medium level's isd; with the
// budget off, at the fast level's. Letting go continues from there to high either way.
TEST_F(Gui, TheDragsFirstLevelIsTheFinestThatFitsTheMotionBudget) {
  const std::string steps = R"([{"wait_level": "high"},
    {"press": [300, 300]}, {"move": [320, 300]}, {"move": [340, 300]}, {"wait_ms": 300},
    {"state": ")" + file("held.json") +
                            R"("}, {"release": [340, 300]}, {"wait_level": "high"}])";
  for (const auto& [budget, isd] : {std::pair{"1000", 1.0}, std::pair{"0", 3.0}}) {
    SCOPED_TRACE(budget);
    const GuiRun run = runScript(steps, std::string(" --motion-budget ") + budget);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const Json held = readJson(dir / "held.json")["runtime"]["shown"];
    EXPECT_EQ(held["level"], "fast");
    EXPECT_DOUBLE_EQ(held["isd"].get<double>(), isd);
    const Json after = readJson(dir / "end.json")["runtime"]["shown"];
    EXPECT_EQ(after["level"], "high");
    EXPECT_DOUBLE_EQ(after["angle_deg"].get<double>(), 340);
  }
}

// The latency breakdown (runtime.latency): every request a drag or key made ends up on screen
// (its own image or a newer one) and the stages of each first frame add up to its input -> screen
// total. Counts and sums only: no time limits here
// (bench/input_latency.sh measures).
TEST_F(Gui, LatencyBreakdownAccountsForEveryInputAndAddsUp) {
  const GuiRun run = runScript(R"([{"wait_level": "high"}, {"key": "Left"}, {"key": "Left"},
    {"drag": {"from": [300, 300], "to": [360, 300], "steps": 6}}, {"wait_level": "high"}])");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json runtime = readJson(dir / "end.json")["runtime"];
  const Json& latency = runtime["latency"];
  std::map<std::string, Json> stage;
  for (const Json& row : latency["stages_ms"]) stage[row["stage"].get<std::string>()] = row;
  // Request 1 is the start-up image; each later one came from input and is on screen now.
  const int inputs = runtime["newest_request"].get<int>() - 1;
  EXPECT_GE(inputs, 8);  // 2 keys, press, 6 moves, release (some may coincide)
  EXPECT_EQ(stage["input_to_screen"]["count"].get<int>(), inputs);
  const int traced = stage["total"]["count"].get<int>();
  ASSERT_GE(traced, 1);
  EXPECT_LE(traced + latency["superseded_requests"].get<int>(), inputs);
  int byLevel = 0;
  for (const char* level : {"fast", "medium", "high"})
    byLevel += latency["first_frame_levels"][level].get<int>();
  EXPECT_EQ(byLevel, traced);
  EXPECT_GE(latency["first_frame_levels"]["fast"].get<int>(), 1);  // the drag's images
  double sum = 0;
  for (const char* name : {"input_to_request", "request_to_pickup", "pickup_to_render", "render",
                           "publish", "publish_to_ui", "upload", "present"}) {
    SCOPED_TRACE(name);
    EXPECT_EQ(stage[name]["count"].get<int>(), traced);
    EXPECT_GE(stage[name]["min"].get<double>(), 0);
    EXPECT_LE(stage[name]["min"].get<double>(), stage[name]["median"].get<double>());
    EXPECT_LE(stage[name]["median"].get<double>(), stage[name]["max"].get<double>());
    sum += stage[name]["mean"].get<double>();
  }
  EXPECT_NEAR(sum, stage["total"]["mean"].get<double>(), 1e-6 * stage["total"]["mean"].get<double>());
  EXPECT_NEAR(stage["worker_busy"]["mean"].get<double>() + stage["wake"]["mean"].get<double>(),
              stage["request_to_pickup"]["mean"].get<double>(),
              1e-6 * (1 + stage["total"]["mean"].get<double>()));
}

TEST_F(Gui, ArrowKeysTurnByOneAndShiftByTenDegrees) {
  const GuiRun run = runScript(R"([{"key": "Left"}, {"key": "Left"}, {"key": "Shift+Right"},
                                {"wait_level": "medium"}])");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json end = readJson(dir / "end.json");
  EXPECT_DOUBLE_EQ(end["state"]["view"]["angle_deg"].get<double>(), 352);
  EXPECT_NEAR(end["runtime"]["shown"]["angle_deg"].get<double>(), 352, 1e-9);
}

TEST_F(Gui, WheelZoomsRightDragPansDoubleClickResets) {
  const std::string steps = R"([
    {"wheel": {"at": [200, 200], "delta": 2}},
    {"drag": {"from": [300, 300], "to": [340, 320], "button": 1, "steps": 4}},
    {"state": ")" + file("zoomed.json") +
                            R"("},
    {"double_click": [300, 300]}])";
  const GuiRun run = runScript(steps);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json zoomed = readJson(dir / "zoomed.json")["state"]["view"];
  EXPECT_NEAR(zoomed["zoom"].get<double>(), 1.44, 1e-9);
  // Zooming about (200, 200) moved the image centre away from the cursor, then the pan added (40, 20).
  const Json reset = readJson(dir / "end.json")["state"]["view"];
  EXPECT_DOUBLE_EQ(reset["zoom"].get<double>(), 1);
  EXPECT_DOUBLE_EQ(reset["pan_px"][0].get<double>(), 0);
  EXPECT_NE(zoomed["pan_px"][0].get<double>(), 0);
  EXPECT_DOUBLE_EQ(reset["angle_deg"].get<double>(), 0);  // panning and zooming do not rotate
}

TEST_F(Gui, TfEditChangesTheImageAndUndoRestoresIt) {
  const Json startup = startupState();
  const Rect plot = rectOf(startup["runtime"]["layout"]["tf_plot"]);
  const std::size_t points = startup["state"]["transfer_function"]["points"].size();
  // A point at about -400 HU, opacity 0.9: fat and soft tissue turn opaque.
  const float x = plot.x0 + (plot.x1 - plot.x0) * float((-400.0 + 1024) / 4095);
  const float y = plot.y0 + (plot.y1 - plot.y0) * 0.1f;
  const std::string steps = R"([
    {"double_click": )" + point(x, y) +
                            R"(},
    {"wait_level": "high"}, {"state": ")" +
                            file("edited.json") + R"("},
    {"key": "Ctrl+Z"},
    {"wait_level": "high"}])";
  const GuiRun run = runScript(steps);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json edited = readJson(dir / "edited.json"), undone = readJson(dir / "end.json");
  EXPECT_EQ(edited["state"]["transfer_function"]["points"].size(), points + 1);
  EXPECT_TRUE(edited["runtime"]["tf_undo_available"].get<bool>());
  EXPECT_NE(edited["runtime"]["shown"]["checksum"], startup["runtime"]["shown"]["checksum"]);
  EXPECT_EQ(undone["state"]["transfer_function"]["points"].size(), points);
  // Rendering is deterministic: the undone TF gives the start-up image back, bit for bit.
  EXPECT_EQ(undone["runtime"]["shown"]["checksum"], startup["runtime"]["shown"]["checksum"]);
}

TEST_F(Gui, RightClickDeletesAControlPoint) {
  const Json startup = startupState();
  const Rect plot = rectOf(startup["runtime"]["layout"]["tf_plot"]);
  const Json& tf = startup["state"]["transfer_function"];
  const std::size_t points = tf["points"].size();
  // The third point of the start-up preset, where the plot draws it.
  const Json& third = tf["points"][2];
  const float x = plot.x0 + (plot.x1 - plot.x0) * float((third["hu"].get<double>() + 1024) / 4095);
  const float y = plot.y1 - (plot.y1 - plot.y0) * third["opacity"].get<float>();
  const GuiRun run =
      runScript(R"([{"click": )" + point(x, y) + R"(, "button": 1}, {"wait_level": "fast"}])");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json end = readJson(dir / "end.json");
  EXPECT_EQ(end["state"]["transfer_function"]["points"].size(), points - 1);
}

TEST_F(Gui, BadScriptIsAOneLineErrorNamingTheFile) {
  const GuiRun run = runScript(R"([{"wait_level": "high"}, {"teleport": [1, 2]}])");
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("script.json"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("step 2"), std::string::npos) << run.output;
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
}

// FNV-1a of 8-bit RGB pixels, as the app's report computes it for the shown image.
std::string checksumOfRgb8(const fs::path& png) {
  OIIO::ImageBuf image(png.string());
  EXPECT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::UINT8));
  const OIIO::ImageSpec& spec = image.spec();
  std::vector<std::uint8_t> pixels(std::size_t(spec.width) * spec.height * 3);
  image.get_pixels(OIIO::ROI(0, spec.width, 0, spec.height, 0, 1, 0, 3), OIIO::TypeDesc::UINT8,
                   pixels.data());
  std::uint64_t hash = 1469598103934665603ull;
  for (std::uint8_t byte : pixels) hash = (hash ^ byte) * 1099511628211ull;
  return std::to_string(hash);
}

TEST_F(Gui, ExportWritesTheShownHighImageAndASidecar) {
  const Json startup = startupState();
  const Json& layout = startup["runtime"]["layout"];
  const Rect path = rectOf(layout["export_path"]), button = rectOf(layout["export_button"]);
  const std::string steps = R"([
    {"click": )" + point(path.midX(), path.midY()) +
                            R"(}, {"key": "Ctrl+A"},
    {"text": ")" + file("view.png") +
                            R"("}, {"key": "Enter"},
    {"click": )" + point(button.midX(), button.midY()) +
                            R"(},
    {"wait_level": "high"}])";
  const GuiRun run = runScript(steps);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json end = readJson(dir / "end.json");
  EXPECT_NE(end["runtime"]["message"].get<std::string>().find("exported"), std::string::npos);
  ASSERT_TRUE(fs::exists(dir / "view.png"));
  // isd 0.5 with the high level's other settings: the very image the viewport shows at high.
  EXPECT_EQ(checksumOfRgb8(dir / "view.png"), end["runtime"]["shown"]["checksum"]);
  const Json sidecar = readJson(dir / "view.png.json");  // io/render_sidecar.h
  EXPECT_EQ(sidecar["image"], file("view.png"));
  EXPECT_DOUBLE_EQ(sidecar["sampling"]["isd"].get<double>(), 0.5);
  EXPECT_EQ(sidecar["sampling"]["filter"], "trilinear");
  EXPECT_EQ(sidecar["view"]["axis"], "k");
  EXPECT_EQ(sidecar["tf"]["points"].size(), end["state"]["transfer_function"]["points"].size());
}

// A session that turns adaptive sampling on for every level: the shown image says so and the
// export (the shown image's bytes) records it in its sidecar, from which `render --params` renders
// it again (ApproximationsCli checks those bytes; this phantom exists only in memory).
TEST_F(Gui, AdaptiveSamplingFromASessionIsShownAndExportedWithItsSettings) {
  const Json adaptive = {{"levels", 2}, {"ray_levels", 5}, {"tolerance", 0.05}};
  const Json session = {{"format", "angioray-session"},
                        {"version", 1},
                        {"levels",
                         {{"fast", {{"adaptive_sampling", adaptive}}},
                          {"medium", {{"adaptive_sampling", adaptive}}},
                          {"high", {{"adaptive_sampling", adaptive}}}}}};
  std::ofstream(file("session.json")) << session.dump();
  // Its settings row in the Rendering panel moves the export section: the layout with the session.
  const GuiRun first = runScript(R"([{"wait_level": "high"}])", " --session " + file("session.json"));
  ASSERT_EQ(first.exitCode, 0) << first.output;
  const Json withSession = readJson(dir / "end.json");
  const Json& layout = withSession["runtime"]["layout"];
  const Rect path = rectOf(layout["export_path"]), button = rectOf(layout["export_button"]);
  const std::string steps = R"([{"wait_level": "high"},
    {"click": )" + point(path.midX(), path.midY()) +
                            R"(}, {"key": "Ctrl+A"}, {"text": ")" + file("view.png") +
                            R"("}, {"key": "Enter"}, {"click": )" + point(button.midX(), button.midY()) +
                            R"(}, {"wait_level": "high"}])";
  const GuiRun run = runScript(steps, " --session " + file("session.json"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json end = readJson(dir / "end.json");
  EXPECT_EQ(end["runtime"]["shown"]["adaptive_sampling"], adaptive);
  ASSERT_TRUE(fs::exists(dir / "view.png")) << end["runtime"]["message"];
  EXPECT_EQ(checksumOfRgb8(dir / "view.png"), end["runtime"]["shown"]["checksum"]);
  EXPECT_EQ(readJson(dir / "view.png.json")["sampling"]["adaptive_sampling"], adaptive);
}

// "..." beside the export file opens the browser at the field's folder with its name typed in; a
// new name typed there fills the field, and Export writes that file.
TEST_F(Gui, TheExportFieldsBrowserChoosesWhereTheImageGoes) {
  const Json startup = startupState();
  const Json& layout = startup["runtime"]["layout"];
  const Rect browse = rectOf(layout["export_browse"]), button = rectOf(layout["export_button"]);
  fs::create_directories(dir / "reports");
  const std::string steps = R"([
    {"click": )" + point(browse.midX(), browse.midY()) +
                            R"(}, {"wait_ms": 50}, {"key": "Ctrl+A"},
    {"text": ")" + file("reports") +
                            R"("}, {"key": "Enter"}, {"wait_ms": 50},
    {"key": "Ctrl+A"}, {"text": "aorta-ap.png"}, {"key": "Enter"}, {"wait_ms": 50},
    {"click": )" + point(button.midX(), button.midY()) +
                            R"(},
    {"wait_level": "high"}])";
  const GuiRun run = runScript(steps);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_TRUE(fs::exists(dir / "reports" / "aorta-ap.png"));
  EXPECT_TRUE(fs::exists(dir / "reports" / "aorta-ap.png.json"));
}

TEST_F(Gui, MissingVolumeIsAOneLineErrorNamingIt) {
  const GuiRun run = runAngioray("gui --headless " + file("nothing.mha"));
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("nothing.mha"), std::string::npos) << run.output;
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
}

bool installed(const char* program) {
  return std::system(("command -v " + std::string(program) + " > /dev/null 2>&1").c_str()) == 0;
}

// The real window (GLFW + OpenGL 3) under Xvfb: xdotool drags on the image, SIGTERM closes the
// window cleanly, and the state it writes on closing shows the angle the drag set.
TEST_F(Gui, WindowUnderXvfbRotatesWithARealMouseDrag) {
  if (!installed("xvfb-run")) GTEST_SKIP() << "xvfb-run not installed (apt package xvfb)";
  if (!installed("xdotool")) GTEST_SKIP() << "xdotool not installed (apt package xdotool)";
  const fs::path session = dir / "session.sh";
  // XDG_CONFIG_HOME: the window writes its last session there when it closes.
  std::ofstream(session) << "XDG_CONFIG_HOME=" + file("config") + " " + std::string(ANGIORAY_BINARY) +
                                " gui --phantom-size 96x96x200 --phantom-style simple --size 800x600 "
                                "--quit-after 60 --state-out " +
                                file("window.json") + " --screenshot " + file("window.png") + R"( &
app=$!
window=$(xdotool search --sync --onlyvisible --name '^angioray$' | head -1)
sleep 1.5
xdotool mousemove --window "$window" 200 300 sleep 0.3 mousedown 1 sleep 0.2   mousemove --window "$window" 230 300 sleep 0.2 mousemove --window "$window" 260 300 sleep 0.2   mousemove --window "$window" 280 300 sleep 0.3 mouseup 1
sleep 1.5
kill -TERM $app
wait $app
)";
  const std::string command =
      "timeout 90 xvfb-run -a -s '-screen 0 1024x768x24' sh " + session.string() + " 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "exit status " << status;
  const Json state = readJson(dir / "window.json");
  // 80 px at 0.5 deg per pixel, dragging right: theta 0 -> 320.
  EXPECT_DOUBLE_EQ(state["state"]["view"]["angle_deg"].get<double>(), 320);
  ASSERT_FALSE(state["runtime"]["shown"].is_null());  // the renderer's images reached the window
  EXPECT_NEAR(state["runtime"]["shown"]["angle_deg"].get<double>(), 320, 1e-9);
  OIIO::ImageBuf shot(file("window.png"));
  ASSERT_TRUE(shot.read());
  EXPECT_EQ(shot.spec().width, 800);
  // Closing wrote the last session, with the angle the drag set.
  const Json last = readJson(dir / "config" / "angioray" / "last-session.json");
  EXPECT_DOUBLE_EQ(last["view"]["angle_deg"].get<double>(), 320);
}

}  // namespace
