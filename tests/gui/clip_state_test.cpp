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
  clip.normalAxis = Axis::j;
  clip.flipNormal = true;
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
}

TEST_F(ClipSession, BadClipValuesAreOneLineErrorsNamingTheKey) {
  const std::pair<std::string, std::string> cases[] = {
      {R"({"clip": []})", "clip is not an object"},
      {R"({"clip": {"crop_on": 1}})", "clip.crop_on"},
      {R"({"clip": {"crop_min_mm": [1, 2]}})", "clip.crop_min_mm"},
      {R"({"clip": {"crop_min_mm": [5, 0, 0], "crop_max_mm": [4, 1, 1]}})", "exceeds"},
      {R"({"clip": {"normal_axis": "x"}})", "clip.normal_axis"},
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
