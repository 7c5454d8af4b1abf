// The VesselGlyph panel through the headless twin: centerlines loaded from the command line or the
// panel, the VesselGlyph checkbox re-renders with regions, the overlay draws the projected
// centerlines over the vessels, broken files are reported and the app keeps running.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <OpenImageIO/imagebuf.h>

#include "tests/support/phantom_folder_test.h"
#include "tests/support/run_angioray.h"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using angio::test_support::runAngioray;

// Tall enough for the side panel down to the VesselGlyph section without scrolling.
const std::string kWindow = " --size 1000x1400 --timeout 120";

struct Box {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  explicit Box(const Json& rect)
      : x0(rect[0].get<float>()), y0(rect[1].get<float>()), x1(rect[2].get<float>()),
        y1(rect[3].get<float>()) {}
  // A point inside the widget's left end (the box of a checkbox, the start of a text field).
  std::string leftEnd() const { return at(x0 + 8, (y0 + y1) / 2); }
  std::string middle() const { return at((x0 + x1) / 2, (y0 + y1) / 2); }
  static std::string at(float x, float y) {
    char text[64];
    std::snprintf(text, sizeof text, "[%.1f, %.1f]", x, y);
    return text;
  }
};

class GuiVessel : public angio::test_support::PhantomFolderTest {
 protected:
  const char* folderPrefix() const override { return "gui-vessel"; }

  // The app on the phantom (plus `extra` options) until the high image shows; its state.
  Json startState(const std::string& extra) {
    const auto run = runAngioray("gui " + file("phantom.nrrd") + " --headless" + kWindow + extra +
                                 " --state-out " + file("start.json"));
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return readJson("start.json");
  }
  angio::test_support::ProgramRun runScript(const std::string& steps, const std::string& extra) {
    std::ofstream(dir / "script.json") << steps;
    return runAngioray("gui " + file("phantom.nrrd") + " --headless" + kWindow + extra + " --script " +
                       file("script.json"));
  }
};

bool isOverlayColor(const float* rgb) { return rgb[0] < 0.45f && rgb[1] > 0.7f && rgb[2] > 0.8f; }

TEST_F(GuiVessel, EnablingVesselGlyphRerendersWithRegionsAndTheOverlayLiesOnTheVessels) {
  const std::string centerlines = " --centerlines " + file("phantom.csv");
  const Json start = startState(centerlines);
  const Json& vgStart = start["runtime"]["vessel_glyph"];
  EXPECT_EQ(vgStart["paths"], 4);
  EXPECT_FALSE(vgStart["enabled"].get<bool>());
  EXPECT_TRUE(vgStart["error"].get<std::string>().empty());
  const Json& layout = start["runtime"]["layout"];
  const std::string steps = R"([
    {"wait_level": "high"}, {"screenshot": ")" +
                            file("plain-overlay.png") + R"("},
    {"click": )" + Box(layout["vg_overlay"]).leftEnd() +
                            R"(}, {"move": [5, 5]}, {"wait_ms": 100},
    {"screenshot": ")" + file("plain.png") +
                            R"("}, {"state": ")" + file("plain.json") + R"("},
    {"click": )" + Box(layout["vg_enable"]).leftEnd() +
                            R"(}, {"move": [5, 5]},
    {"wait_level": "high"}, {"state": ")" +
                            file("vg.json") + R"("}])";
  const auto run = runScript(steps, centerlines);
  ASSERT_EQ(run.exitCode, 0) << run.output;

  const Json plain = readJson("plain.json"), vg = readJson("vg.json");
  EXPECT_FALSE(plain["runtime"]["vessel_glyph"]["overlay"].get<bool>());
  EXPECT_FALSE(plain["runtime"]["vessel_glyph"]["rendering"].get<bool>());
  EXPECT_TRUE(vg["runtime"]["vessel_glyph"]["enabled"].get<bool>());
  EXPECT_TRUE(vg["runtime"]["vessel_glyph"]["rendering"].get<bool>());
  EXPECT_EQ(vg["runtime"]["shown"]["level"], "high");
  EXPECT_GT(vg["runtime"]["shown"]["request"].get<int>(),
            plain["runtime"]["shown"]["request"].get<int>());
  EXPECT_NE(vg["runtime"]["shown"]["checksum"], plain["runtime"]["shown"]["checksum"]);

  // The overlay's pixels: the centerlines projected with the shown view lie on rendered vessels
  // (not on the black background) in the same image without the overlay.
  OIIO::ImageBuf withOverlay(file("plain-overlay.png")), without(file("plain.png"));
  ASSERT_TRUE(withOverlay.read() && without.read());
  const Box viewport(plain["runtime"]["layout"]["viewport"]);
  long overlayPixels = 0, onImage = 0, overlayColoredWithout = 0;
  for (int y = int(viewport.y0) + 30; y < int(viewport.y1) - 40; ++y) {  // captions, scale bar apart
    for (int x = int(viewport.x0); x < int(viewport.x1); ++x) {
      float a[3], b[3];
      withOverlay.getpixel(x, y, a, 3);
      without.getpixel(x, y, b, 3);
      if (isOverlayColor(b)) ++overlayColoredWithout;
      if (!isOverlayColor(a)) continue;
      ++overlayPixels;
      if (b[0] + b[1] + b[2] > 0.1f) ++onImage;
    }
  }
  std::printf("overlay pixels %ld, on the rendered image %ld, overlay-colored without it %ld\n",
              overlayPixels, onImage, overlayColoredWithout);
  EXPECT_GT(overlayPixels, 500);
  EXPECT_LT(overlayColoredWithout, overlayPixels / 20);
  EXPECT_GT(onImage, overlayPixels * 95 / 100);
}

TEST_F(GuiVessel, BrokenCenterlineFileIsReportedAndTheAppKeepsRunning) {
  std::ofstream(dir / "broken.csv") << "path,x_mm,y_mm,z_mm,radius_mm\n0,1,2,nan,1\n0,1,2\n";
  const Json start = startState(" --centerlines " + file("broken.csv"));
  const Json& vgStart = start["runtime"]["vessel_glyph"];
  EXPECT_EQ(vgStart["paths"], 0);
  EXPECT_NE(vgStart["error"].get<std::string>().find("broken.csv"), std::string::npos) << vgStart;
  EXPECT_NE(start["runtime"]["message"].get<std::string>().find("broken.csv"), std::string::npos);
  EXPECT_EQ(start["runtime"]["shown"]["level"], "high");  // rendered as usual

  // Then the good file through the panel's path field and button.
  const Json& layout = start["runtime"]["layout"];
  const std::string steps = R"([
    {"click": )" + Box(layout["vg_path"]).middle() +
                            R"(}, {"key": "Ctrl+A"},
    {"text": ")" + file("phantom.csv") +
                            R"("}, {"key": "Enter"},
    {"click": )" + Box(layout["vg_load"]).middle() +
                            R"(}, {"wait_level": "high"},
    {"state": ")" + file("loaded.json") +
                            R"("}])";
  const auto run = runScript(steps, " --centerlines " + file("broken.csv"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json loaded = readJson("loaded.json");
  EXPECT_EQ(loaded["runtime"]["vessel_glyph"]["paths"], 4);
  EXPECT_TRUE(loaded["runtime"]["vessel_glyph"]["error"].get<std::string>().empty());
  EXPECT_NE(loaded["runtime"]["message"].get<std::string>().find("loaded 4 centerline paths"),
            std::string::npos);
}

TEST_F(GuiVessel, TfEditorSwitchesToTheFocusTf) {
  const std::string centerlines = " --centerlines " + file("phantom.csv");
  const Json start = startState(centerlines);
  const Json& layout = start["runtime"]["layout"];
  const std::string steps = R"([
    {"click": )" + Box(layout["vg_enable"]).leftEnd() +
                            R"(}, {"wait_level": "high"},
    {"state": ")" + file("before.json") +
                            R"("},
    {"click": )" + Box(layout["vg_edit_focus"]).leftEnd() +
                            R"(}, {"wait_ms": 100},
    {"double_click": )" + Box(layout["tf_plot"]).middle() +
                            R"(}, {"move": [5, 5]},
    {"wait_level": "high"}, {"state": ")" +
                            file("after.json") + R"("}])";
  const auto run = runScript(steps, centerlines);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json before = readJson("before.json"), after = readJson("after.json");
  EXPECT_EQ(after["runtime"]["vessel_glyph"]["tf_editing"], "focus");
  // The point went into the focus TF (now edited), not the main TF, and the image changed.
  EXPECT_EQ(after["state"]["transfer_function"], before["state"]["transfer_function"]);
  EXPECT_NE(after["runtime"]["vessel_glyph"]["focus_tf"], "cta-vessels");
  EXPECT_NE(after["runtime"]["shown"]["checksum"], before["runtime"]["shown"]["checksum"]);
}

// Until the user sets them, the focus and context TFs follow the main TF: loading another main TF
// with VesselGlyph on (the outside clipped, so the main TF renders nothing by itself) changes the
// VesselGlyph image, and the regions still report that they follow.
TEST_F(GuiVessel, RegionTfsFollowALoadedMainTf) {
  const std::string centerlines = " --centerlines " + file("phantom.csv");
  std::ofstream(file("blue.json")) << R"({"name": "blue lumen", "points": [
      {"hu": -1024, "color": [0, 0, 0], "opacity": 0}, {"hu": 150, "color": [0.1, 0.2, 0.9], "opacity": 0},
      {"hu": 400, "color": [0.2, 0.4, 1.0], "opacity": 0.8}, {"hu": 3071, "color": [1, 1, 1], "opacity": 0.8}]})";
  const Json start = startState(centerlines);
  const Json& layout = start["runtime"]["layout"];
  const std::string steps = R"([
    {"click": )" + Box(layout["vg_enable"]).leftEnd() +
                            R"(}, {"wait_level": "high"}, {"state": ")" + file("before.json") + R"("},
    {"click": )" + Box(layout["tf_path"]).middle() +
                            R"(}, {"key": "Ctrl+A"}, {"text": ")" + file("blue.json") + R"("},
    {"click": )" + Box(layout["tf_load"]).middle() +
                            R"(}, {"wait_level": "high"}, {"state": ")" + file("after.json") + R"("}])";
  const auto run = runScript(steps, centerlines);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json before = readJson("before.json"), after = readJson("after.json");
  ASSERT_TRUE(after["runtime"]["vessel_glyph"]["rendering"].get<bool>());
  EXPECT_EQ(after["state"]["transfer_function"]["name"], "blue lumen");
  EXPECT_EQ(after["runtime"]["vessel_glyph"]["focus_tf"], "main TF");
  EXPECT_EQ(after["runtime"]["vessel_glyph"]["context_tf"], "main TF, faded");
  EXPECT_NE(after["runtime"]["shown"]["checksum"], before["runtime"]["shown"]["checksum"]);
}

TEST_F(GuiVessel, CprHoverMarksTheCenterlineOnTheDvrAndADvrClickThereMovesTheCprCursorBack) {
  const std::string centerlines = " --centerlines " + file("phantom.csv");
  const Json start = startState(centerlines);
  const Json& layout = start["runtime"]["layout"];
  const std::string open = R"([
    {"click": )" + Box(layout["cpr_shown"]).leftEnd() +
                           R"(}, {"move": [5, 5]}, {"wait_level": "high"},
    {"state": ")" + file("cpr.json") +
                           R"("}])";
  ASSERT_EQ(runScript(open, centerlines).exitCode, 0);
  const Json shown = readJson("cpr.json");
  const Json& cpr = shown["runtime"]["vessel_glyph"]["cpr"];
  ASSERT_TRUE(cpr["shown"].get<bool>()) << cpr;
  ASSERT_EQ(cpr["mode"], "straightened");
  const double pixelMm = cpr["pixel_mm"].get<double>();
  // All paths side by side (vessel/cpr_layout.h): rows where the paths share their trunk (the
  // phantom's aorta, the first ~140 mm) are one span with the centerline in the image's middle
  // column; row y shows arc length (y + 0.5) D.
  const int centreColumn = cpr["width"].get<int>() / 2, row = int(60 / pixelMm);
  const Box image(shown["runtime"]["layout"]["cpr_image"]);
  const float scale = (image.x1 - image.x0) / cpr["width"].get<float>();
  const std::string hover =
      Box::at(image.x0 + (centreColumn + 0.5f) * scale, image.y0 + (row + 0.5f) * scale);
  const std::string steps = R"([
    {"click": )" + Box(layout["cpr_shown"]).leftEnd() +
                            R"(}, {"move": [5, 5]}, {"wait_level": "high"},
    {"move": )" + hover + R"(}, {"wait_ms": 100}, {"screenshot": ")" +
                            file("hover.png") + R"("},
    {"state": ")" + file("hover.json") +
                            R"("}])";
  ASSERT_EQ(runScript(steps, centerlines).exitCode, 0);
  const Json hovered = readJson("hover.json")["runtime"]["vessel_glyph"]["cpr"]["hovered"];
  ASSERT_TRUE(hovered.is_object()) << hovered;
  EXPECT_NEAR(hovered["arc_mm"].get<double>(), (row + 0.5) * pixelMm, pixelMm);
  EXPECT_GT(hovered["hu"].get<double>(), 150);  // contrast-filled lumen

  // The mark on the DVR image sits on the overlay's projected centerline (within 2 pixels).
  OIIO::ImageBuf shot(file("hover.png"));
  ASSERT_TRUE(shot.read());
  const int markX = int(hovered["dvr_screen"][0].get<float>()),
            markY = int(hovered["dvr_screen"][1].get<float>());
  bool onOverlay = false;
  for (int y = markY - 2; y <= markY + 2; ++y)
    for (int x = markX - 2; x <= markX + 2; ++x) {
      float rgb[3];
      shot.getpixel(x, y, rgb, 3);
      onOverlay = onOverlay || isOverlayColor(rgb);
    }
  EXPECT_TRUE(onOverlay) << "mark at " << markX << ", " << markY;

  // Clicking the DVR image at that mark puts the CPR cursor back on the hovered centerline point.
  const std::string click = R"([
    {"click": )" + Box(layout["cpr_shown"]).leftEnd() +
                            R"(}, {"move": [5, 5]}, {"wait_level": "high"},
    {"click": )" + Box::at(float(hovered["dvr_screen"][0]), float(hovered["dvr_screen"][1])) +
                            R"(},
    {"move": [5, 5]}, {"wait_ms": 100}, {"state": ")" +
                            file("click.json") + R"("}])";
  ASSERT_EQ(runScript(click, centerlines).exitCode, 0);
  const Json cursor = readJson("click.json")["runtime"]["vessel_glyph"]["cpr"]["cursor"];
  ASSERT_TRUE(cursor.is_object()) << cursor;
  EXPECT_NEAR(cursor["arc_mm"].get<double>(), hovered["arc_mm"].get<double>(), 3.0);
  ASSERT_TRUE(cursor.contains("cpr_pixel")) << cursor;
  EXPECT_NEAR(cursor["cpr_pixel"][0].get<double>(), centreColumn, 3.0);
  EXPECT_NEAR(cursor["cpr_pixel"][1].get<double>(), row, 3.0 / pixelMm);
}

// The CPR pane as a reading view: the wheel zooms about the pointer (the CPR pixel under it stays),
// a right drag sets the window 4 HU per pixel, a click puts the cursor on the clicked line's
// centerline point (in the slices too) with the cross-section inset, a double click fits again.
TEST_F(GuiVessel, CprPaneZoomsAboutThePointerSetsTheWindowAndPutsTheCursorWithItsSection) {
  const std::string centerlines = " --centerlines " + file("phantom.csv");
  const Json start = startState(centerlines);
  const std::string open = R"({"click": )" + Box(start["runtime"]["layout"]["cpr_shown"]).leftEnd() +
                           R"(}, {"move": [5, 5]}, {"wait_level": "high"})";
  ASSERT_EQ(
      runScript("[" + open + R"(, {"state": ")" + file("open.json") + R"("}])", centerlines).exitCode,
      0);
  const Json opened = readJson("open.json");
  const Json& cpr = opened["runtime"]["vessel_glyph"]["cpr"];
  const Box image(opened["runtime"]["layout"]["cpr_image"]);
  const float scale = (image.x1 - image.x0) / cpr["width"].get<float>();
  const int centreColumn = cpr["width"].get<int>() / 2, row = int(60 / cpr["pixel_mm"].get<double>());
  const float x = image.x0 + (centreColumn + 0.5f) * scale, y = image.y0 + (row + 0.5f) * scale;
  const std::string at = Box::at(x, y);
  const std::string steps = "[" + open + R"(,
    {"move": )" + at + R"(}, {"wait_ms": 50}, {"state": ")" +
                            file("before.json") + R"("},
    {"wheel": {"at": )" + at +
                            R"(, "delta": 3}}, {"move": )" + at + R"(}, {"wait_ms": 50},
    {"state": ")" + file("zoomed.json") +
                            R"("},
    {"drag": {"from": )" + at +
                            R"(, "to": )" + Box::at(x + 25, y - 10) + R"(, "button": 1, "steps": 5}},
    {"click": )" + at + R"(}, {"move": )" +
                            at + R"(}, {"wait_ms": 100},
    {"screenshot": ")" + file("pane.png") +
                            R"("}, {"state": ")" + file("clicked.json") + R"("},
    {"key": "Down"}, {"key": "Down"}, {"key": "Shift+Down"}, {"key": "Up"}, {"wait_ms": 50},
    {"state": ")" + file("stepped.json") +
                            R"("},
    {"double_click": )" + at +
                            R"(}, {"wait_ms": 50}, {"state": ")" + file("fitted.json") + R"("}])";
  const auto run = runScript(steps, centerlines);
  ASSERT_EQ(run.exitCode, 0) << run.output;

  const Json before = readJson("before.json"), zoomed = readJson("zoomed.json");
  const Json &hoveredBefore = before["runtime"]["vessel_glyph"]["cpr"]["hovered"],
             &hoveredZoomed = zoomed["runtime"]["vessel_glyph"]["cpr"]["hovered"];
  // (On failure, everything that decides the hover: the pane's runtime, zoom and layout.)
  ASSERT_TRUE(hoveredBefore.is_object() && hoveredZoomed.is_object())
      << "before: " << before["runtime"]["vessel_glyph"]["cpr"]
      << "\nzoomed: " << zoomed["runtime"]["vessel_glyph"]["cpr"] << "\n"
      << zoomed["state"]["cpr"] << "\n"
      << zoomed["runtime"]["layout"] << "\npointer at " << at;
  EXPECT_NEAR(zoomed["state"]["cpr"]["zoom"].get<double>(), 1.2 * 1.2 * 1.2, 1e-9);
  const Box zoomedImage(zoomed["runtime"]["layout"]["cpr_image"]);
  EXPECT_NEAR((zoomedImage.x1 - zoomedImage.x0) / (image.x1 - image.x0), 1.728, 0.01);
  // The same CPR pixel under the pointer: the same arc length (one pixel at the first scale).
  EXPECT_NEAR(hoveredZoomed["arc_mm"].get<double>(), hoveredBefore["arc_mm"].get<double>(),
              cpr["pixel_mm"].get<double>());

  const Json clicked = readJson("clicked.json");
  const Json& state = clicked["state"]["cpr"];
  EXPECT_DOUBLE_EQ(state["window"].get<double>(), 800 + 4 * 25);  // right: wider
  EXPECT_DOUBLE_EQ(state["level"].get<double>(), 250 - 4 * 10);   // up: lower
  const Json& cursor = clicked["runtime"]["vessel_glyph"]["cpr"]["cursor"];
  ASSERT_TRUE(cursor.is_object()) << cursor;
  EXPECT_NEAR(cursor["arc_mm"].get<double>(), hoveredZoomed["arc_mm"].get<double>(), 1e-6);
  EXPECT_NEAR(cursor["cpr_pixel"][0].get<double>(), centreColumn, 1.0);
  // The slices follow: their cursor is the clicked line's centerline point, which the DVR marks.
  ASSERT_TRUE(clicked["state"]["slices"]["cursor_mm"].is_array()) << clicked["state"]["slices"];
  EXPECT_TRUE(clicked["runtime"]["layout"].contains("cpr_section"));  // the inset is drawn
  // Nothing of it asked the 3-D view for an image (a press in the pane is not a turn of the view).
  EXPECT_EQ(clicked["runtime"]["newest_request"], before["runtime"]["newest_request"]);
  // The arrow keys step the cursor along its path, 1 mm (Shift: 10 mm), the slices with it; the
  // document (and so a session) keeps it.
  const Json stepped = readJson("stepped.json");
  const Json& steppedCursor = stepped["state"]["cpr"]["cursor"];
  ASSERT_TRUE(steppedCursor.is_object()) << stepped["state"]["cpr"];
  EXPECT_EQ(steppedCursor["path"], cursor["path"]);
  EXPECT_NEAR(steppedCursor["arc_mm"].get<double>(), cursor["arc_mm"].get<double>() + 11, 1e-9);
  EXPECT_NE(stepped["state"]["slices"]["cursor_mm"], clicked["state"]["slices"]["cursor_mm"]);
  EXPECT_NEAR(stepped["runtime"]["vessel_glyph"]["cpr"]["cursor"]["cpr_pixel"][1].get<double>(),
              cursor["cpr_pixel"][1].get<double>() + 11 / cpr["pixel_mm"].get<double>(), 1.0);
  EXPECT_EQ(stepped["state"]["view"]["angle_deg"], clicked["state"]["view"]["angle_deg"]);
  const Json fitted = readJson("fitted.json");
  EXPECT_EQ(fitted["state"]["cpr"]["zoom"], 1.0);
  EXPECT_EQ(fitted["state"]["cpr"]["pan_px"], Json({0.0, 0.0}));
}

}  // namespace
