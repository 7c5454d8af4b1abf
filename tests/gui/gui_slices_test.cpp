// The linked slice view in the headless app: a session shows it, the cursor starts at the volume's
// centre; a click in the axial slice moves the cursor to the voxel under it (from the slice's drawn
// rectangle and the volume's size, not from the app's own mapping), the wheel over the coronal
// slice steps its index, a right-drag in the sagittal slice widens the window; a click on the
// aorta in the 3-D image puts the cursor on its visible lumen.
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/phantom_folder_test.h"

namespace angio {
namespace {

using Json = nlohmann::json;
using test_support::runAngioray;

class GuiSlices : public test_support::PhantomFolderTest {
 protected:
  const char* folderPrefix() const override { return "gui-slices"; }
  void SetUp() override {
    PhantomFolderTest::SetUp();
    std::ofstream(dir / "session.json")
        << R"({"format": "angioray-session", "slices": {"shown": true}, "transfer_function":
              {"name": "lumen", "points": [{"hu": -1024, "color": [0, 0, 0], "opacity": 0},
              {"hu": 150, "color": [1, 0.3, 0.2], "opacity": 0}, {"hu": 300, "color": [1, 0.5, 0.4],
              "opacity": 0.8}, {"hu": 3071, "color": [1, 1, 1], "opacity": 0.9}]}})";
  }
  // Runs `steps`, then waits for the high level and writes the state to NAME.json.
  Json run(const std::string& steps, const std::string& name) {
    std::ofstream(dir / "script.json")
        << "[" << steps << (steps.empty() ? "" : ", ") << R"({"wait_level": "high"}, {"state": ")"
        << file(name + ".json") << R"("}, {"screenshot": ")" << file(name + ".png") << "\"}]";
    auto result =
        runAngioray("gui " + file("phantom.nrrd") + " --headless --size 1400x900 --timeout 120" +
                    " --session " + file("session.json") + " --script " + file("script.json"));
    EXPECT_EQ(result.exitCode, 0) << result.output;
    return readJson(name + ".json");
  }
};

std::string at(double x, double y) { return "[" + std::to_string(x) + ", " + std::to_string(y) + "]"; }

TEST_F(GuiSlices, ClicksWheelAndRightDragMoveTheCursorAndSetTheWindow) {
  const Json start = run("", "start");
  const Json& slices = start["runtime"]["slices"];
  ASSERT_TRUE(slices["shown"].get<bool>()) << slices;
  EXPECT_EQ(slices["cursor_voxel"], Json::parse("[48, 48, 100]"));  // the centre of 96x96x200 (rounded)
  const Json layout = start["runtime"]["layout"];
  ASSERT_FALSE(layout["slice_axial_image"].is_null()) << layout;
  EXPECT_EQ(slices["panes"]["axial"]["width"], 96);
  EXPECT_EQ(slices["panes"]["coronal"]["height"], 200);

  // The axial image spans i across and j down: a click a quarter across and three quarters down
  // lands in voxel (24, 72) (pixel centres), k unchanged.
  const Json& axial = layout["slice_axial_image"];
  const double x =
      axial[0].get<double>() + (axial[2].get<double>() - axial[0].get<double>()) * 24.5 / 96;
  const double y =
      axial[1].get<double>() + (axial[3].get<double>() - axial[1].get<double>()) * 72.5 / 96;
  const Json& coronal = layout["slice_coronal"];
  const Json& sagittal = layout["slice_sagittal"];
  const double cx = (coronal[0].get<double>() + coronal[2].get<double>()) / 2,
               cy = (coronal[1].get<double>() + coronal[3].get<double>()) / 2;
  const double sx = (sagittal[0].get<double>() + sagittal[2].get<double>()) / 2,
               sy = (sagittal[1].get<double>() + sagittal[3].get<double>()) / 2;
  const Json moved = run(R"({"click": )" + at(x, y) + R"(}, {"wheel": {"at": )" + at(cx, cy) +
                             R"(, "delta": 3}}, {"drag": {"from": )" + at(sx, sy) + R"(, "to": )" +
                             at(sx + 50, sy) + R"(, "button": 1}})",
                         "moved");
  const Json& after = moved["runtime"]["slices"];
  // The wheel stepped the coronal slice (j) by three from the clicked 72.
  EXPECT_EQ(after["cursor_voxel"], Json::parse("[24, 75, 100]")) << after;
  EXPECT_EQ(moved["state"]["slices"]["window"].get<double>(), 600 + 50 * 4) << moved["state"]["slices"];
  EXPECT_EQ(moved["state"]["slices"]["level"].get<double>(), 250);
  // The slice gestures asked the 3-D view for nothing: no request after the start-up one (a press
  // counted as a 3-D interaction would have asked for an interactive render).
  EXPECT_EQ(moved["runtime"]["newest_request"], start["runtime"]["newest_request"]);
}

// Ctrl+wheel zooms a pane about the pointer (the voxel under it stays) without stepping the slice,
// a middle drag pans it by the drag, a double click fits it again; the other panes keep their view.
TEST_F(GuiSlices, CtrlWheelZoomsAPaneAboutThePointerAMiddleDragPansADoubleClickFits) {
  const Json start = run("", "start");
  const Json& image = start["runtime"]["layout"]["slice_axial_image"];
  const double x0 = image[0], y0 = image[1], x1 = image[2], y1 = image[3];
  const double x = x0 + (x1 - x0) * 0.3, y = y0 + (y1 - y0) * 0.6;
  const Json hovered = run(R"({"move": )" + at(x, y) + "}", "hovered");
  const Json voxel = hovered["runtime"]["slices"]["hovered_voxel"];
  ASSERT_TRUE(voxel.is_array()) << hovered["runtime"]["slices"];
  const std::string zoom = R"({"move": )" + at(x, y) + R"(}, {"wheel": {"at": )" + at(x, y) +
                           R"(, "delta": 2, "hold": "Ctrl"}})";
  const Json zoomed = run(zoom + R"(, {"move": )" + at(x, y) + "}", "zoomed");
  const Json& pane = zoomed["state"]["slices"]["panes"]["axial"];
  EXPECT_NEAR(pane["zoom"].get<double>(), 1.44, 1e-9) << pane;
  EXPECT_EQ(zoomed["runtime"]["slices"]["hovered_voxel"], voxel);
  EXPECT_EQ(zoomed["runtime"]["slices"]["cursor_voxel"], start["runtime"]["slices"]["cursor_voxel"]);
  const Json& zoomedImage = zoomed["runtime"]["layout"]["slice_axial_image"];
  EXPECT_NEAR(zoomedImage[2].get<double>() - zoomedImage[0].get<double>(), 1.44 * (x1 - x0), 1.0);
  EXPECT_EQ(zoomed["state"]["slices"]["panes"]["coronal"]["zoom"], 1.0);

  const Json panned = run(zoom + R"(, {"drag": {"from": )" + at(x, y) + R"(, "to": )" +
                              at(x + 30, y - 20) + R"(, "button": 2, "steps": 4}})",
                          "panned");
  const Json& pan = panned["state"]["slices"]["panes"]["axial"]["pan_px"];
  EXPECT_NEAR(pan[0].get<double>() - pane["pan_px"][0].get<double>(), 30, 1e-6) << pan;
  EXPECT_NEAR(pan[1].get<double>() - pane["pan_px"][1].get<double>(), -20, 1e-6) << pan;
  EXPECT_EQ(panned["runtime"]["slices"]["cursor_voxel"], start["runtime"]["slices"]["cursor_voxel"]);

  const Json fitted = run(zoom + R"(, {"double_click": )" + at(x, y) + "}", "fitted");
  EXPECT_EQ(fitted["state"]["slices"]["panes"]["axial"],
            Json::parse(R"({"zoom": 1.0, "pan_px": [0.0, 0.0]})"));
  EXPECT_EQ(fitted["runtime"]["layout"]["slice_axial_image"], image);
}

TEST_F(GuiSlices, AClickOnTheImagePutsTheCursorOnTheVisibleSurface) {
  const Json start = run("", "start");
  // A point of the aorta's centerline (the phantom's 200th, physical mm): its lumen is what the
  // TF shows there.
  std::ifstream csv(dir / "phantom.csv");
  std::string line;
  for (int n = 0; n < 200 && std::getline(csv, line); ++n) {
  }
  std::stringstream fields(line);
  std::string path, x, y, z;
  std::getline(fields, path, ',');
  std::getline(fields, x, ',');
  std::getline(fields, y, ',');
  std::getline(fields, z, ',');
  const Json picked =
      run(R"({"wait_level": "high"}, {"click_mm": [)" + x + ", " + y + ", " + z + "]}", "picked");
  const Json& slices = picked["runtime"]["slices"];
  EXPECT_NE(slices["cursor_voxel"], start["runtime"]["slices"]["cursor_voxel"])
      << picked["runtime"]["message"];
  EXPECT_GT(slices["hu"].get<double>(), 100) << slices;  // contrast-filled lumen, not air or fat
}

}  // namespace
}  // namespace angio
