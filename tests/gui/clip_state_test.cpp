// The Crop & clip section's state: what view clipping it stands for, how the workstation applies
// it (a new dataset starts unclipped), and the session file's "clip" keys: saved and loaded back
// field for field, missing keys keep the defaults, bad values are one line naming the key.
#include <gtest/gtest.h>

#include "gui/clip_state.h"
#include "gui/session_file.h"
#include "gui/workstation.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

// Every field away from its default.
ClipState unusualClip() {
  ClipState clip;
  clip.cropOn = true;
  clip.crop = CropBox{{1.0 / 3, 20.5, 0}, {100.25, 200, 1e3 / 7}};
  clip.planeOn = true;
  clip.facingViewer = false;
  clip.normal = glm::dvec3(0, -1, 0);
  clip.planeOffsetMm = -12.125;
  clip.slabOn = true;
  clip.slab = ThickSlab{7.0 / 3, 33.5};
  return clip;
}

TEST(ClipState, StandsForTheViewClippingInTheVolumesMillimetres) {
  const glm::dvec3 extent(200, 300, 800);
  EXPECT_FALSE(viewClippingOf(ClipState{}, extent).any());
  const ViewClipping clipping = viewClippingOf(unusualClip(), extent);
  EXPECT_EQ(clipping.crop, unusualClip().crop);
  EXPECT_EQ(clipping.slab, unusualClip().slab);
  // Normal -j, the centre (100, 150, 400) moved 12.125 mm against it.
  ASSERT_TRUE(clipping.plane);
  EXPECT_EQ(clipping.plane->normal, glm::dvec3(0, -1, 0));
  EXPECT_EQ(clipping.plane->pointMm, glm::dvec3(100, 162.125, 400));
  ClipState facing = unusualClip();
  facing.facingViewer = true;
  EXPECT_EQ(viewClippingOf(facing, extent).plane, facingPlane(-12.125));
  // Switched off, a part is not rendered but keeps its values.
  facing.cropOn = facing.planeOn = facing.slabOn = false;
  EXPECT_FALSE(viewClippingOf(facing, extent).any());
  EXPECT_EQ(facing.crop, unusualClip().crop);
}

TEST(ClipState, AnObliquePlaneCutsAcrossItsUnitNormalWithinTheProjectedExtent) {
  const glm::dvec3 extent(200, 300, 800);
  ClipState clip = unusualClip();
  clip.normal = glm::dvec3(2, -4, 4);  // length 6
  const ViewClipping clipping = viewClippingOf(clip, extent);
  ASSERT_TRUE(clipping.plane);
  const glm::dvec3 unit(1.0 / 3, -2.0 / 3, 2.0 / 3);
  EXPECT_NEAR(glm::length(clipping.plane->normal - unit), 0, 1e-15);
  EXPECT_NEAR(glm::length(clipping.plane->pointMm - (extent * 0.5 - 12.125 * unit)), 0, 1e-12);
  // Half the extent projected on the normal: (200 + 600 + 1600) / 3 / 2.
  EXPECT_DOUBLE_EQ(planeReachMm(unit, extent), 400);
  EXPECT_DOUBLE_EQ(planeReachMm(glm::dvec3(0, -1, 0), extent), 150);
  clip.normal = glm::dvec3(0.0);  // never a zero normal to the renderer
  EXPECT_EQ(clipNormalOf(clip), glm::dvec3(1, 0, 0));
}

TEST(ClipState, AzimuthAndElevationGiveTheNormalAndBack) {
  EXPECT_NEAR(glm::length(normalFromAngles({0, 0}) - glm::dvec3(1, 0, 0)), 0, 1e-15);
  EXPECT_NEAR(glm::length(normalFromAngles({90, 0}) - glm::dvec3(0, 1, 0)), 0, 1e-15);
  EXPECT_NEAR(glm::length(normalFromAngles({0, -90}) - glm::dvec3(0, 0, -1)), 0, 1e-15);
  const glm::dvec3 n = normalFromAngles({-135, 30});
  EXPECT_NEAR(n.z, 0.5, 1e-15);
  EXPECT_NEAR(n.x, n.y, 1e-15);
  EXPECT_LT(n.x, 0);
  const glm::dvec2 back = anglesOfNormal(n);
  EXPECT_NEAR(back.x, -135, 1e-12);
  EXPECT_NEAR(back.y, 30, 1e-12);
  EXPECT_EQ(anglesOfNormal(glm::dvec3(0, 0, 2)), glm::dvec2(0, 90));  // azimuth 0 along k
}

// A facing plane at depth 12 removes what lies in front of centre + 12 d; fixed, it is the plane
// through that point with the normal towards the viewer, for that view.
TEST(ClipState, FixingTheFacingPlaneKeepsTheCutOfTheCurrentView) {
  const glm::dvec3 extent(200, 300, 800), viewDir(0.6, 0.8, 0);
  ClipState facing;
  facing.planeOn = true;
  facing.planeOffsetMm = 12;
  const ClipState fixed = fixedToView(facing, -viewDir);
  EXPECT_FALSE(fixed.facingViewer);
  const ViewClipping clipping = viewClippingOf(fixed, extent);
  ASSERT_TRUE(clipping.plane);
  EXPECT_NEAR(glm::length(clipping.plane->normal + viewDir), 0, 1e-15);
  EXPECT_NEAR(glm::length(clipping.plane->pointMm - (extent * 0.5 + 12.0 * viewDir)), 0, 1e-12);
  EXPECT_EQ(fixedToView(fixed, glm::dvec3(0, 0, 1)), fixed);  // a fixed plane stays as it is
}

TEST(ClipState, TheWorkstationAppliesItAndANewDatasetStartsUnclipped) {
  Workstation station;
  station.apply(ClipEdit{unusualClip()});
  EXPECT_EQ(station.document().clip, unusualClip());
  const auto version = station.version();
  station.apply(ClipEdit{unusualClip()});
  EXPECT_EQ(station.version(), version);  // nothing changed
  station.apply(DatasetOpened{"/data/other.mha"});
  EXPECT_EQ(station.document().clip, ClipState{});
}

class ClipSession : public test_support::TempFolderTest {};

TEST_F(ClipSession, SavedClipLoadsBackFieldForField) {
  Document session;
  session.tf.points = {{-1024, {0, 0, 0}, 0}, {300, {1, 0, 0}, 0.5}};
  session.clip = unusualClip();
  saveSession(session, dir_ / "s.json");
  EXPECT_EQ(loadSession(dir_ / "s.json").clip, unusualClip());
  // A session from before the section: nothing clipped.
  EXPECT_EQ(parseSession(R"({"dataset": "x.mha"})", dir_ / "old.json").clip, ClipState{});
  EXPECT_EQ(parseSession(R"({"clip": {"slab_on": true}})", dir_ / "part.json").clip.slab,
            ClipState{}.slab);
  // A session from before oblique planes: a voxel axis, maybe flipped.
  EXPECT_EQ(parseSession(R"({"clip": {"normal_axis": "j", "flip_normal": true}})", dir_ / "a.json")
                .clip.normal,
            glm::dvec3(0, -1, 0));
  const glm::dvec3 oblique =
      parseSession(R"({"clip": {"normal": [0, 3, -4]}})", dir_ / "o.json").clip.normal;
  EXPECT_NEAR(glm::length(oblique - glm::dvec3(0, 0.6, -0.8)), 0, 1e-15);
}

TEST_F(ClipSession, BadClipValuesAreOneLineErrorsNamingTheKey) {
  const std::pair<std::string, std::string> cases[] = {
      {R"({"clip": []})", "clip is not an object"},
      {R"({"clip": {"crop_on": 1}})", "clip.crop_on"},
      {R"({"clip": {"crop_min_mm": [1, 2]}})", "clip.crop_min_mm"},
      {R"({"clip": {"crop_min_mm": [5, 0, 0], "crop_max_mm": [4, 1, 1]}})", "exceeds"},
      {R"({"clip": {"normal_axis": "x"}})", "clip.normal_axis"},
      {R"({"clip": {"normal": [0, 0, 0]}})", "clip.normal is not a direction"},
      {R"({"clip": {"normal": [1, 0]}})", "clip.normal is not [x, y, z]"},
      {R"({"clip": {"slab_thickness_mm": 0}})", "clip.slab_thickness_mm"},
      {R"({"clip": {"plane_offset_mm": "far"}})", "clip.plane_offset_mm"},
  };
  for (const auto& [text, problem] : cases) {
    const auto file = write("bad.json", text);
    test_support::expectInputError([&] { loadSession(file); }, file, problem);
  }
}

}  // namespace
}  // namespace angio
