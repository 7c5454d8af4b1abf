// The clipping in render sidecars (render/recipe_json.h "clipping"): crop box, clip plane (fixed
// or facing the viewer) and slab survive save + load exactly, sidecars from before clipping load
// with nothing clipped, and broken clipping gives one line naming the key.
#include <string>

#include <gtest/gtest.h>

#include "io/input_error.h"
#include "render/recipe_json.h"
#include "tests/support/replaced_once.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

RenderRecipe clipped(const ClipPlane& plane) {
  RenderRecipe s;
  s.dataset = "/data/p.mha";
  s.tf.points = {{-1024, {0, 0, 0}, 0}, {300, {1, 0, 0}, 0.4}};
  s.params.clipping.crop = CropBox{{1.0 / 3, 2.5, -7}, {100.125, 1e3 / 7, 64}};
  s.params.clipping.plane = plane;
  s.params.clipping.slab = ThickSlab{-12.0 / 11, 0.1 + 1e-14};
  return s;
}

class RecipeClipping : public test_support::TempFolderTest {
 protected:
  std::string loadError(const std::string& name, const std::string& text) const {
    try {
      parseRenderSidecar(text, dir_ / name);
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  }
};

TEST_F(RecipeClipping, EveryPartSurvivesSaveAndLoadExactly) {
  const ClipPlane fixed{false, 0, {10.1, 20.2, 1.0 / 3}, {0.3, -0.7, 1e-3}};
  const ClipPlane facing = facingPlane(-2.0 / 3);
  for (const ClipPlane& plane : {fixed, facing}) {
    const RenderRecipe s = clipped(plane);
    const auto file = dir_ / "c.png.json";
    saveRenderSidecar(s, file);
    const RenderRecipe r = loadRenderSidecar(file);
    EXPECT_EQ(r.params.clipping, s.params.clipping) << plane.facingViewer;
    EXPECT_EQ(r, s);
    EXPECT_EQ(renderSidecarJson(r), renderSidecarJson(s));  // --params writes the same sidecar
  }
}

TEST_F(RecipeClipping, NothingClippedIsNullAndASidecarWithoutClippingLoads) {
  RenderRecipe s = clipped({});
  s.params.clipping = {};
  const std::string json = renderSidecarJson(s);
  EXPECT_NE(json.find("\"crop\": null"), std::string::npos);
  EXPECT_NE(json.find("\"plane\": null"), std::string::npos);
  EXPECT_NE(json.find("\"slab\": null"), std::string::npos);
  // As sidecars were written before clipping existed (tests/golden/sidecars).
  std::string old = json;
  const std::size_t begin = old.find("  \"clipping\"");
  old.erase(begin, old.find("  \"tf\"") - begin);
  ASSERT_EQ(old.find("clipping"), std::string::npos);
  EXPECT_FALSE(parseRenderSidecar(old, dir_ / "old.json").params.clipping.any());
}

TEST_F(RecipeClipping, BrokenClippingGivesOneLineNamingTheKey) {
  const std::string good = renderSidecarJson(clipped({false, 0, {1, 2, 3}, {0, 0, 1}}));
  auto replaced = [&](const std::string& from, const std::string& to) {
    return test_support::replacedOnce(good, from, to);
  };
  struct Case {
    std::string text, mention;
  };
  const Case cases[] = {
      {replaced("\"min_mm\": [", "\"min_mm\": [1, "), "clipping.crop.min_mm"},
      {replaced("\"max_mm\": [", "\"max_mm\": [-1000, -1000, -1000, "), "clipping.crop.max_mm"},
      {replaced("\"max_mm\"", "\"maximum\""), "clipping.crop.max_mm"},
      {replaced("\"normal\": [", "\"normal\": [\"x\", "), "clipping.plane.normal"},
      {replaced("\"facing_viewer\": false", "\"facing_viewer\": 0"), "clipping.plane.facing_viewer"},
      {replaced("\"thickness_mm\": ", "\"thickness_mm\": -"), "thickness"},
      {replaced("\"offset_mm\": ", "\"offset_mm\": \"deep\", \"x\": "), "clipping.slab.offset_mm"},
  };
  for (const Case& c : cases) {
    const std::string message = loadError("broken.json", c.text);
    EXPECT_EQ(message.rfind((dir_ / "broken.json").string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(c.mention), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  // A crop box whose minimum exceeds its maximum.
  RenderRecipe empty = clipped({false, 0, {1, 2, 3}, {0, 0, 1}});
  empty.params.clipping.crop->minMm.y = 500;
  EXPECT_NE(loadError("empty.json", renderSidecarJson(empty)).find("j minimum exceeds"),
            std::string::npos);
}

TEST_F(RecipeClipping, MetadataSaysWhatWasClippedInTheFlagsWords) {
  const ImageMetadata metadata = renderSidecarMetadata(clipped(facingPlane(2.5)));
  EXPECT_EQ(metadata.at("clip"), "facing viewer, offset 2.5 mm");
  EXPECT_EQ(metadata.at("crop_mm").rfind("0.3333333333,100.125,2.5,", 0), 0u) << metadata.at("crop_mm");
  EXPECT_FALSE(renderSidecarMetadata(RenderRecipe{}).contains("crop_mm"));
}

}  // namespace
}  // namespace angio
