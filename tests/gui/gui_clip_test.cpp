// The Crop & clip section in the headless app: opened (it starts closed), its "thick slab"
// checkbox turns the slab on, which changes the shown image and leaves the rays outside it
// black; an export of that view writes a sidecar with the slab, from which `angioray render
// --params` (another process) renders the same pixels.
#include <cmath>
#include <fstream>
#include <string>

#include <glm/glm.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/phantom_folder_test.h"
#include "tests/support/png_pixels.h"
#include "tests/support/widget_points.h"

namespace angio {
namespace {

using Json = nlohmann::json;
using test_support::runAngioray;

const std::string kWindow = " --size 1000x1600 --timeout 120";

class GuiClip : public test_support::PhantomFolderTest {
 protected:
  const char* folderPrefix() const override { return "gui-clip"; }
  test_support::ProgramRun run(const std::string& steps) {
    std::ofstream(dir / "script.json") << steps;
    return runAngioray("gui " + file("phantom.nrrd") + " --headless" + kWindow + " --script " +
                       file("script.json"));
  }
  // Waits for the high level and writes the state to NAME.json and a screenshot to NAME.png.
  std::string record(const std::string& name) const {
    return R"({"wait_level": "high"}, {"state": ")" + file(name + ".json") + R"("}, {"screenshot": ")" +
           file(name + ".png") + "\"}";
  }
};

TEST_F(GuiClip, TheSlabCheckboxChangesTheImageAndAnExportKeepsTheSlab) {
  auto closed = run("[" + record("closed") + "]");
  ASSERT_EQ(closed.exitCode, 0) << closed.output;
  const Json header = readJson("closed.json")["runtime"]["layout"]["section_Crop & clip"];
  ASSERT_FALSE(header.is_null());
  const std::string open = R"({"click": )" + test_support::middleOf(header) + R"(}, {"wait_ms": 100})";
  auto opened = run("[" + open + ", " + record("open") + "]");
  ASSERT_EQ(opened.exitCode, 0) << opened.output;
  const Json layout = readJson("open.json")["runtime"]["layout"];
  ASSERT_FALSE(layout["clip_slab"].is_null()) << layout;
  const Json plain = readJson("open.json");
  EXPECT_FALSE(plain["state"]["clip"]["slab_on"].get<bool>());

  // The slab's sliders push the Export section down: its widgets are where they are with it on.
  const std::string slabOn = R"({"click": )" + test_support::leftEnd(layout["clip_slab"]) + "}";
  auto slab = run("[" + open + ", " + slabOn + ", " + record("slab") + "]");
  ASSERT_EQ(slab.exitCode, 0) << slab.output;
  const Json state = readJson("slab.json");
  EXPECT_TRUE(state["state"]["clip"]["slab_on"].get<bool>()) << state["state"]["clip"];
  EXPECT_NE(state["runtime"]["shown"]["checksum"], plain["runtime"]["shown"]["checksum"]);
  const Json& slabLayout = state["runtime"]["layout"];
  const std::string exportView = R"({"click": )" + test_support::middleOf(slabLayout["export_path"]) +
                                 R"(}, {"key": "Ctrl+A"}, {"text": ")" + file("view.png") +
                                 R"("}, {"key": "Enter"}, {"click": )" +
                                 test_support::middleOf(slabLayout["export_button"]) + "}";
  auto exported = run("[" + open + ", " + slabOn + R"(, {"wait_level": "high"}, )" + exportView +
                      R"(, {"wait_level": "high"}])");
  ASSERT_EQ(exported.exitCode, 0) << exported.output;

  // The default slab is 20 mm thick: far less of the phantom shows than without it.
  ASSERT_TRUE(std::filesystem::exists(file("view.png"))) << exported.output;
  const Json sidecar = readJson("view.png.json");
  EXPECT_EQ(sidecar["clipping"]["slab"]["thickness_mm"], 20.0) << sidecar["clipping"];
  EXPECT_TRUE(sidecar["clipping"]["crop"].is_null());
  auto again = runAngioray("render --params " + file("view.png.json") + " --out " + file("again.png"));
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_EQ(test_support::pixelsOf(file("again.png")).values,
            test_support::pixelsOf(file("view.png")).values);
  // The same sidecar without the slab.
  Json withoutSlab = sidecar;
  withoutSlab["clipping"]["slab"] = nullptr;
  std::ofstream(file("unclipped.json")) << withoutSlab.dump();
  auto unclipped =
      runAngioray("render --params " + file("unclipped.json") + " --out " + file("unclipped.png"));
  ASSERT_EQ(unclipped.exitCode, 0) << unclipped.output;
  const auto lit = [](const test_support::Pixels& image) {
    int count = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) count += image.at(x, y)[0] > 0;
    return count;
  };
  EXPECT_LT(lit(test_support::pixelsOf(file("view.png"))),
            lit(test_support::pixelsOf(file("unclipped.png"))) * 3 / 4);
}

// The crop box's handles: a left drag on the top face's handle lowers that face by the drag's
// length along the face's screen direction, and does not turn the view.
TEST_F(GuiClip, DraggingACropHandleMovesItsFaceAndDoesNotTurnTheView) {
  auto start = run("[" + record("closed") + "]");
  ASSERT_EQ(start.exitCode, 0) << start.output;
  const Json closed = readJson("closed.json");
  const std::string open = R"({"click": )" +
                           test_support::middleOf(closed["runtime"]["layout"]["section_Crop & clip"]) +
                           R"(}, {"wait_ms": 100})";
  auto opened = run("[" + open + ", " + record("open") + "]");
  ASSERT_EQ(opened.exitCode, 0) << opened.output;
  const std::string cropOn =
      R"({"click": )" + test_support::leftEnd(readJson("open.json")["runtime"]["layout"]["clip_crop"]) +
      "}";
  auto cropped = run("[" + open + ", " + cropOn + ", " + record("crop") + "]");
  ASSERT_EQ(cropped.exitCode, 0) << cropped.output;
  const Json before = readJson("crop.json");
  ASSERT_TRUE(before["state"]["clip"]["crop_on"].get<bool>());
  Json top;
  for (const Json& handle : before["runtime"]["crop_handles"])
    if (handle["axis"] == 2 && handle["at_max"].get<bool>()) top = handle;
  ASSERT_FALSE(top.is_null()) << before["runtime"]["crop_handles"];

  const double x = top["at"][0], y = top["at"][1], dragPx = 60;
  const std::string drag = R"({"drag": {"from": [)" + std::to_string(x) + ", " + std::to_string(y) +
                           R"(], "to": [)" + std::to_string(x) + ", " + std::to_string(y + dragPx) +
                           R"(], "steps": 6}})";
  auto dragged = run("[" + open + ", " + cropOn + R"(, {"wait_level": "high"}, )" + drag + ", " +
                     record("dragged") + "]");
  ASSERT_EQ(dragged.exitCode, 0) << dragged.output;
  const Json after = readJson("dragged.json");
  const double perMm = std::hypot(top["px_per_mm"][0].get<double>(), top["px_per_mm"][1].get<double>());
  const double wantMm = before["state"]["clip"]["crop_max_mm"][2].get<double>() - dragPx / perMm;
  EXPECT_NEAR(after["state"]["clip"]["crop_max_mm"][2].get<double>(), wantMm, 0.5 / perMm + 1e-6);
  EXPECT_EQ(after["state"]["clip"]["crop_min_mm"], before["state"]["clip"]["crop_min_mm"]);
  EXPECT_EQ(after["state"]["view"]["angle_deg"], before["state"]["view"]["angle_deg"]);
  EXPECT_NE(after["runtime"]["shown"]["checksum"], before["runtime"]["shown"]["checksum"]);
}

// Pixels of the two screenshots' viewport image (`rect` of the layout) that differ by more than 8
// in any channel, as a fraction of the image.
double differingShare(const test_support::Pixels& a, const test_support::Pixels& b, const Json& rect) {
  const int x0 = int(rect[0].get<double>()) + 1, y0 = int(rect[1].get<double>()) + 1,
            x1 = int(rect[2].get<double>()) - 1, y1 = int(rect[3].get<double>()) - 1;
  int differing = 0, all = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x, ++all)
      for (int c = 0; c < 3; ++c)
        if (std::abs(a.at(x, y)[c] - b.at(x, y)[c]) > 8) {
          ++differing;
          break;
        }
  return all > 0 ? double(differing) / all : 1.0;
}

// Fix turns the facing plane into a plane fixed in the volume with the same cut: the image stays,
// the normal points at the viewer across the view's axis; turning the view then turns the cut
// with the volume, unlike a facing plane's.
TEST_F(GuiClip, FixingTheFacingPlaneKeepsItsCutAndTurnsItWithTheVolume) {
  auto start = run("[" + record("closed") + "]");
  ASSERT_EQ(start.exitCode, 0) << start.output;
  const std::string open =
      R"({"click": )" +
      test_support::middleOf(readJson("closed.json")["runtime"]["layout"]["section_Crop & clip"]) +
      R"(}, {"wait_ms": 100})";
  auto opened = run("[" + open + ", " + record("open") + "]");
  ASSERT_EQ(opened.exitCode, 0) << opened.output;
  const std::string planeOn =
      R"({"click": )" + test_support::leftEnd(readJson("open.json")["runtime"]["layout"]["clip_plane"]) +
      R"(}, {"move": [5, 5]})";
  auto facing = run("[" + open + ", " + planeOn + ", " + record("facing") + "]");
  ASSERT_EQ(facing.exitCode, 0) << facing.output;
  const Json facingState = readJson("facing.json");
  ASSERT_FALSE(facingState["runtime"]["layout"]["clip_fix"].is_null());
  const std::string fix = R"({"click": )" +
                          test_support::middleOf(facingState["runtime"]["layout"]["clip_fix"]) +
                          R"(}, {"move": [5, 5]})";
  const std::string turn = R"({"key": "Shift+Left"}, {"key": "Shift+Left"}, {"key": "Shift+Left"})";
  auto fixed = run("[" + open + ", " + planeOn + ", " + fix + ", " + record("fixed") + ", " + turn +
                   ", " + record("fixed-turned") + "]");
  ASSERT_EQ(fixed.exitCode, 0) << fixed.output;
  auto facingTurned =
      run("[" + open + ", " + planeOn + ", " + turn + ", " + record("facing-turned") + "]");
  ASSERT_EQ(facingTurned.exitCode, 0) << facingTurned.output;

  const Json fixedState = readJson("fixed.json");
  const Json& clip = fixedState["state"]["clip"];
  EXPECT_FALSE(clip["facing_viewer"].get<bool>()) << clip;
  const int axis = std::string("ijk").find(fixedState["state"]["view"]["axis"].get<std::string>());
  const glm::dvec3 normal(clip["normal"][0], clip["normal"][1], clip["normal"][2]);
  EXPECT_NEAR(glm::length(normal), 1, 1e-12);
  EXPECT_NEAR(normal[axis], 0, 1e-12);  // the view looks across its axis
  const Json rect = facingState["runtime"]["layout"]["viewport_image"];
  EXPECT_EQ(fixedState["runtime"]["layout"]["viewport_image"], rect);
  // The same cut: at most float rounding at the cut's edge tells the two images apart.
  EXPECT_LT(differingShare(test_support::pixelsOf(file("facing.png")),
                           test_support::pixelsOf(file("fixed.png")), rect),
            0.005);
  // 30 degrees on: the fixed plane's normal stays in the volume, the facing one turned with the view.
  const Json turned = readJson("fixed-turned.json");
  EXPECT_EQ(turned["state"]["clip"]["normal"], clip["normal"]);
  EXPECT_NE(turned["state"]["view"]["angle_deg"], fixedState["state"]["view"]["angle_deg"]);
  EXPECT_GT(differingShare(test_support::pixelsOf(file("fixed-turned.png")),
                           test_support::pixelsOf(file("facing-turned.png")),
                           turned["runtime"]["layout"]["viewport_image"]),
            0.02);
}

}  // namespace
}  // namespace angio
