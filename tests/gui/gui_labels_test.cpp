// The Labels section end to end in the headless app: labels read at start and counted, automatic
// removal hides bone and table, undo gives the labels back, a saved .seg.nrrd reads back the same,
// and the images after a change are those of a fresh start with its labels.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/phantom_folder_test.h"
#include "tests/support/temp_folder_test.h"
#include "tests/support/widget_points.h"

namespace angio {
namespace {

using Json = nlohmann::json;
using test_support::runAngioray;

const std::string kWindow = " --size 1000x1400 --timeout 120";

using test_support::middleOf;

class GuiLabels : public test_support::PhantomFolderTest {
 protected:
  const char* folderPrefix() const override { return "gui-labels"; }
  bool withLabels() const override { return true; }
  test_support::ProgramRun run(const std::string& steps, const std::string& extra = "") {
    std::ofstream(dir / "script.json") << steps;
    return runAngioray("gui " + file("phantom.nrrd") + " --headless" + kWindow + extra + " --script " +
                       file("script.json"));
  }
  // The layout with the Labels section open (it starts closed).
  Json openLayout(const std::string& extra) {
    auto first = run(R"([{"wait_level": "high"}, {"state": ")" + file("closed.json") + "\"}]", extra);
    EXPECT_EQ(first.exitCode, 0) << first.output;
    const Json header = readJson("closed.json")["runtime"]["layout"]["section_Labels"];
    openClick = R"({"click": )" + middleOf(header) + R"(}, {"wait_ms": 100})";
    auto second =
        run("[" + openClick + R"(, {"wait_level": "high"}, {"state": ")" + file("open.json") + "\"}]",
            extra);
    EXPECT_EQ(second.exitCode, 0) << second.output;
    return readJson("open.json")["runtime"]["layout"];
  }
  std::string openClick;
};

TEST_F(GuiLabels, LabelsReadAtStartAreCountedRemovalHidesBoneAndTableAndUndoGivesThemBack) {
  const std::string labels = " --labels " + file("truth.nrrd");
  const Json layout = openLayout(labels);
  const Json start = readJson("open.json");
  const Json& counted = start["runtime"]["labels"]["voxels"];
  ASSERT_FALSE(counted.is_null());
  EXPECT_GT(counted[1].get<double>(), 0);  // bone
  EXPECT_GT(counted[2].get<double>(), 0);  // table
  EXPECT_FALSE(start["runtime"]["labels"]["dirty"].get<bool>());
  EXPECT_NE(start["state"]["labels"]["file"].get<std::string>().find("truth.nrrd"), std::string::npos);

  const auto removal = run("[" + openClick + R"(, {"wait_level": "high"}, {"click": )" +
                               middleOf(layout["labels_remove_bone"]) +
                               R"(}, {"wait_ms": 300}, {"wait_level": "high"}, {"state": ")" +
                               file("removed.json") + "\"}]",
                           labels);
  ASSERT_EQ(removal.exitCode, 0) << removal.output;
  const Json removed = readJson("removed.json");
  // Two steps to undo: reading the file at start, then the removal.
  EXPECT_EQ(removed["runtime"]["labels"]["undo"], 2) << removed["runtime"]["labels"];
  EXPECT_TRUE(removed["runtime"]["labels"]["dirty"].get<bool>());
  const Json& styles = removed["state"]["transfer_function"]["labels"];
  ASSERT_GE(styles.size(), 2u) << styles;
  for (const Json& style : styles) EXPECT_EQ(style["mode"], "hidden") << style;

  // Undo after the removal gives back the file's labels, voxel for voxel in the counts.
  const auto undone = run("[" + openClick + R"(, {"wait_level": "high"}, {"click": )" +
                              middleOf(layout["labels_remove_bone"]) +
                              R"(}, {"wait_ms": 300}, {"wait_level": "high"}, {"click": )" +
                              middleOf(layout["labels_undo"]) +
                              R"(}, {"wait_level": "high"}, {"state": ")" + file("undone.json") + "\"}]",
                          labels);
  ASSERT_EQ(undone.exitCode, 0) << undone.output;
  const Json after = readJson("undone.json")["runtime"]["labels"];
  EXPECT_EQ(after["voxels"], counted) << after;
  EXPECT_EQ(after["redo"], 1);
}

TEST_F(GuiLabels, SavedSegmentationReadsBackWithTheSameCounts) {
  const std::string labels = " --labels " + file("truth.nrrd");
  const Json layout = openLayout(labels);
  const Json counts = readJson("open.json")["runtime"]["labels"]["voxels"];
  const auto save = run("[" + openClick + R"(, {"wait_level": "high"}, {"click": )" +
                            middleOf(layout["labels_path"]) + R"(}, {"key": "Ctrl+A"}, {"text": ")" +
                            file("saved.seg.nrrd") + R"("}, {"key": "Enter"}, {"click": )" +
                            middleOf(layout["labels_save"]) + R"(}, {"wait_ms": 100}])",
                        labels);
  ASSERT_EQ(save.exitCode, 0) << save.output;
  ASSERT_TRUE(std::filesystem::exists(file("saved.seg.nrrd")));
  openLayout(" --labels " + file("saved.seg.nrrd"));
  EXPECT_EQ(readJson("open.json")["runtime"]["labels"]["voxels"], counts);
}

TEST_F(GuiLabels, AnExportWithUnsavedLabelsWritesThemBesideItAndItsSidecarRendersTheSameBytes) {
  const std::string labels = " --labels " + file("truth.nrrd");
  const Json layout = openLayout(labels);
  // Give a piece back (the labels change and are not saved), then export the view.
  const auto exported = run(
      "[" + openClick + R"(, {"wait_level": "high"}, {"click": )" +
          middleOf(layout["labels_remove_bone"]) +
          R"(}, {"wait_ms": 300}, {"wait_level": "high"}, {"click": )" +
          middleOf(layout["export_path"]) + R"(}, {"key": "Ctrl+A"}, {"text": ")" + file("view.png") +
          R"("}, {"key": "Enter"}, {"click": )" + middleOf(layout["export_button"]) +
          R"(}, {"wait_level": "high"}, {"state": ")" + file("exported.json") + "\"}]",
      labels);
  ASSERT_EQ(exported.exitCode, 0) << exported.output;
  ASSERT_TRUE(readJson("exported.json")["runtime"]["labels"]["dirty"].get<bool>());
  ASSERT_TRUE(std::filesystem::exists(file("view.png")))
      << readJson("exported.json")["runtime"]["message"];
  const Json sidecar = readJson("view.png.json");
  EXPECT_EQ(sidecar["labels"], file("view.png.labels.seg.nrrd"));
  ASSERT_TRUE(std::filesystem::exists(file("view.png.labels.seg.nrrd")));
  const auto again =
      runAngioray("render --params " + file("view.png.json") + " -o " + file("again.png"));
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_EQ(test_support::fileBytes(file("view.png")), test_support::fileBytes(file("again.png")));
}

// A label change keeps the renderer's slice tiles and refreshes the slices it touched
// (render/frame_renderer.h TilesAhead), or, over most slices, comes with tiles its job built
// (core/slice_tiles.h LabelOverlay): the images shown after it are those of a fresh start with
// the same labels. Removal hides bone and table; its undo gives them back, which tiles that missed
// the undo would skip as hidden.
TEST_F(GuiLabels, ImagesAfterARemovalAndItsUndoAreThoseOfAFreshStart) {
  const Json layout = openLayout("");
  const Json fresh = readJson("open.json")["runtime"]["shown"];
  ASSERT_EQ(fresh["level"], "high");
  const std::string removal = "[" + openClick + R"(, {"wait_level": "high"}, {"click": )" +
                              middleOf(layout["labels_remove_bone"]) +
                              R"(}, {"wait_ms": 300}, {"wait_level": "high"}, {"state": ")" +
                              file("removed.json") + "\"}";
  const auto removing = run(removal + "]");
  ASSERT_EQ(removing.exitCode, 0) << removing.output;
  const Json removed = readJson("removed.json")["runtime"];  // the label list grew: a new layout
  const Json& after = removed["layout"];
  const auto changes = run(removal + R"(, {"click": )" + middleOf(after["labels_path"]) +
                           R"(}, {"key": "Ctrl+A"}, {"text": ")" + file("removed.seg.nrrd") +
                           R"("}, {"key": "Enter"}, {"click": )" + middleOf(after["labels_save"]) +
                           R"(}, {"wait_ms": 100}, {"click": )" + middleOf(after["labels_undo"]) +
                           R"(}, {"wait_level": "high"}, {"state": ")" + file("undone.json") + "\"}]");
  ASSERT_EQ(changes.exitCode, 0) << changes.output;
  const Json undone = readJson("undone.json")["runtime"];
  ASSERT_EQ(undone["labels"]["redo"], 1) << undone["labels"];
  // The removal touched every slice: its job built the tiles, and the undo's job too.
  EXPECT_TRUE(removed["labels"]["tiles_built_ahead"].get<bool>());
  EXPECT_TRUE(undone["labels"]["tiles_built_ahead"].get<bool>());
  EXPECT_EQ(undone["message"], "undid bone and table removal");
  ASSERT_EQ(removed["shown"]["level"], "high");
  ASSERT_EQ(undone["shown"]["level"], "high");
  EXPECT_NE(removed["shown"]["checksum"], fresh["checksum"]);  // the bone went
  EXPECT_EQ(undone["shown"]["checksum"], fresh["checksum"]);

  ASSERT_TRUE(std::filesystem::exists(file("removed.seg.nrrd"))) << undone["message"];
  openLayout(" --labels " + file("removed.seg.nrrd"));
  const Json startedRemoved = readJson("open.json")["runtime"]["shown"];
  ASSERT_EQ(startedRemoved["level"], "high");
  EXPECT_EQ(startedRemoved["checksum"], removed["shown"]["checksum"]);
}

}  // namespace
}  // namespace angio
