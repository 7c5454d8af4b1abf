// The workstation model: apply() is the one place the document changes; it keeps the angle in
// [0, 360), turns VesselGlyph on with the hybrid, bumps the version only on a change.
#include "gui/workstation.h"

#include <gtest/gtest.h>

#include "gui/tf_targets.h"
#include "render/region_tfs.h"

namespace angio {
namespace {

TransferFunction twoPointTf(double hu) {
  TransferFunction tf;
  tf.name = "test";
  tf.points = {{hu, {1, 0, 0}, 0.0}, {hu + 100, {1, 1, 1}, 0.5}};
  return tf;
}

TEST(GuiWorkstation, EqualDocumentsCompareEqualAndAnyFieldTellsThemApart) {
  Document a, b;
  EXPECT_EQ(a, b);
  b.vesselGlyph.settings.cleft = !a.vesselGlyph.settings.cleft;
  EXPECT_NE(a, b);
  b = a;
  b.panelsOpen["View"] = false;
  EXPECT_NE(a, b);
}

TEST(GuiWorkstation, ViewEditsAndTurnsKeepTheAngleInZeroTo360) {
  Workstation workstation;
  ViewState view;
  view.angleDeg = 370;
  workstation.apply(ViewEdit{view});
  EXPECT_DOUBLE_EQ(workstation.document().view.angleDeg, 10);
  workstation.apply(RotateEdit{-20});
  EXPECT_DOUBLE_EQ(workstation.document().view.angleDeg, 350);
  workstation.apply(RotateEdit{10});
  EXPECT_DOUBLE_EQ(workstation.document().view.angleDeg, 0);
}

TEST(GuiWorkstation, AStartingDocumentIsNormalised) {
  Document start;
  start.view.angleDeg = -90;
  start.cpr.hybrid = true;
  const Workstation workstation(start);
  EXPECT_DOUBLE_EQ(workstation.document().view.angleDeg, 270);
  EXPECT_TRUE(workstation.document().vesselGlyph.enabled);
  EXPECT_EQ(workstation.version(), 0u);
}

TEST(GuiWorkstation, TurningTheHybridOnTurnsVesselGlyphOnAndVesselGlyphMayBeTurnedOffAgain) {
  Workstation workstation;
  ASSERT_FALSE(workstation.document().vesselGlyph.enabled);
  CprState cpr = workstation.document().cpr;
  cpr.hybrid = true;
  workstation.apply(CprEdit{cpr});
  EXPECT_TRUE(workstation.document().vesselGlyph.enabled);

  VesselGlyphState off = workstation.document().vesselGlyph;
  off.enabled = false;
  workstation.apply(VesselGlyphEdit{off});
  EXPECT_FALSE(workstation.document().vesselGlyph.enabled);  // the CPR section says the hybrid waits
  cpr.transitionMm = 2;
  workstation.apply(CprEdit{cpr});  // the hybrid was on already: not turned on by this edit
  EXPECT_FALSE(workstation.document().vesselGlyph.enabled);
}

TEST(GuiWorkstation, ASessionKeepsTheDatasetAndRecentFilesAndItsHybridTurnsVesselGlyphOn) {
  Document start;
  start.dataset = "phantom 64x64x64";
  start.recentFiles = {"/data/a.mha"};
  start.cpr.hybrid = true;  // already on: the session's hybrid must still bring VesselGlyph
  Workstation workstation(start);
  VesselGlyphState off = workstation.document().vesselGlyph;
  off.enabled = false;
  workstation.apply(VesselGlyphEdit{off});

  Document session;
  session.dataset = "/data/b.mha";
  session.recentFiles = {"/data/c.mha"};
  session.view.angleDeg = 725;
  session.cpr.hybrid = true;
  session.tf = twoPointTf(100);
  workstation.apply(SessionEdit{session});
  const Document& document = workstation.document();
  EXPECT_EQ(document.dataset, "phantom 64x64x64");
  EXPECT_EQ(document.recentFiles, std::vector<std::string>{"/data/a.mha"});
  EXPECT_DOUBLE_EQ(document.view.angleDeg, 5);
  EXPECT_TRUE(document.vesselGlyph.enabled);
  EXPECT_EQ(document.tf, session.tf);
}

TEST(GuiWorkstation, TheVersionGoesUpWithEveryChangeAndOnlyThen) {
  Workstation workstation;
  EXPECT_EQ(workstation.version(), 0u);
  workstation.apply(PanelOpenEdit{"View", true});
  EXPECT_EQ(workstation.version(), 1u);
  workstation.apply(PanelOpenEdit{"View", true});  // as it is: no change
  EXPECT_EQ(workstation.version(), 1u);
  workstation.apply(RotateEdit{360});  // wraps back to where it was
  EXPECT_EQ(workstation.version(), 1u);
  workstation.apply(RotateEdit{1});
  EXPECT_EQ(workstation.version(), 2u);
}

TEST(GuiWorkstation, AnOpenedDatasetStartsZoomAndPanOverAndHeadsTheRecentFiles) {
  Document start;
  start.view.zoom = 3;
  start.view.panPx = {10, -4};
  start.recentFiles = {"/data/a.mha", "/data/b.mha"};
  Workstation workstation(start);
  workstation.apply(DatasetOpened{"/data/b.mha"});
  const Document& document = workstation.document();
  EXPECT_EQ(document.dataset, "/data/b.mha");
  EXPECT_DOUBLE_EQ(document.view.zoom, 1);
  EXPECT_EQ(document.view.panPx, glm::dvec2(0.0));
  EXPECT_EQ(document.recentFiles, (std::vector<std::string>{"/data/b.mha", "/data/a.mha"}));
}

// The old dataset's vessel state, as a user leaves it: centerlines loaded, VesselGlyph, the CPR
// view with the hybrid, a crop box.
Document withVesselState() {
  Document d;
  d.dataset = "/data/a.mha";
  d.vesselGlyph.centerlines = "a.csv";
  d.vesselGlyph.centerlinesAbsolute = "/data/a.csv";
  d.vesselGlyph.enabled = true;
  d.cpr.shown = d.cpr.hybrid = true;
  d.cpr.cursor = CprCursor{0, 25};
  d.vessels.paths = {VesselPath{}};
  d.labels.file = "/data/a-labels.nrrd";
  d.clip.cropOn = true;
  return d;
}

TEST(GuiWorkstation, ANewDatasetDropsWhatBelongedToTheOldOneAndListsIt) {
  const Document before = withVesselState();
  EXPECT_EQ(droppedByNewDataset(before),
            (std::vector<std::string>{"1 vessel path", "the centerline file", "VesselGlyph",
                                      "the CPR view", "the labels", "the crop & clip"}));
  Workstation workstation(before);
  workstation.apply(DatasetOpened{"/data/b.mha"});
  const Document& after = workstation.document();
  EXPECT_TRUE(after.vesselGlyph.centerlines.empty());
  EXPECT_TRUE(after.vesselGlyph.centerlinesAbsolute.empty());
  EXPECT_FALSE(after.vesselGlyph.enabled);
  EXPECT_FALSE(after.cpr.shown);
  EXPECT_FALSE(after.cpr.hybrid);
  EXPECT_FALSE(after.cpr.cursor);  // it was on the old paths
  EXPECT_TRUE(after.vessels.paths.empty());
  EXPECT_TRUE(after.labels.file.empty());
  EXPECT_EQ(after.clip, ClipState{});
  EXPECT_TRUE(droppedByNewDataset(after).empty());
}

TEST(GuiWorkstation, ANewDatasetStartsTheSliceCursorAtItsCentreAndKeepsTheSliceSettings) {
  Document before;
  before.slices = {true, glm::dvec3(10, 20, 30), {2000, 500}};
  before.slices.panes[0].zoom = 3;  // the zoom and pan fitted the old dataset's slices
  Workstation workstation(before);
  workstation.apply(DatasetOpened{"/data/b.mha"});
  EXPECT_EQ(workstation.document().slices, (SliceViewState{true, std::nullopt, {2000, 500}}));
  Workstation ofSession(before);
  ofSession.apply(DatasetOpened{"/data/a.mha", true});
  EXPECT_EQ(ofSession.document().slices, before.slices);  // the session's own cursor
}

TEST(GuiWorkstation, ASessionsDatasetKeepsTheSessionsVesselGlyphCprAndClipping) {
  Workstation workstation(withVesselState());
  workstation.apply(DatasetOpened{"/data/a.mha", true});
  const Document& after = workstation.document();
  EXPECT_EQ(after.vesselGlyph.centerlines, "a.csv");
  EXPECT_TRUE(after.vesselGlyph.enabled);
  EXPECT_TRUE(after.cpr.shown && after.cpr.hybrid);
  EXPECT_TRUE(after.clip.cropOn);
  EXPECT_EQ(after.cpr.cursor, (CprCursor{0, 25}));
  EXPECT_TRUE(after.vessels.paths.empty());  // App brings the session's paths back once it loaded
}

TEST(GuiWorkstation, ATfChangeGoesToItsTargetWithItsPreset) {
  Workstation workstation;
  workstation.apply(TfChange{TfTarget::focus, twoPointTf(200), ""});
  workstation.apply(TfChange{TfTarget::main, twoPointTf(-100), "cta"});
  const Document& document = workstation.document();
  EXPECT_EQ(document.vesselGlyph.focusTf, twoPointTf(200));
  EXPECT_EQ(document.vesselGlyph.focusPreset, "");
  EXPECT_TRUE(document.vesselGlyph.contextTf.points.empty());
  EXPECT_EQ(document.tf, twoPointTf(-100));
  EXPECT_EQ(document.tfPreset, "cta");
  EXPECT_EQ(tfOf(document, TfTarget::focus), twoPointTf(200));
  EXPECT_FALSE(document.vesselGlyph.focusFollowsMain);  // set by the user: no longer follows
  EXPECT_TRUE(document.vesselGlyph.contextFollowsMain);
}

// Until the user gives a region its own TF it renders with the main TF (the context faded by the
// opacity modulator), whatever the main TF becomes; asked to, it follows again.
TEST(GuiWorkstation, RegionTfsFollowTheMainTfUntilSetAndAgainWhenAsked) {
  Workstation workstation;
  workstation.apply(TfChange{TfTarget::main, twoPointTf(300), "x"});
  const Document& document = workstation.document();
  EXPECT_EQ(tfOf(document, TfTarget::focus), twoPointTf(300));
  const TransferFunction context = tfOf(document, TfTarget::context);
  EXPECT_EQ(context.points, twoPointTf(300).points);
  EXPECT_DOUBLE_EQ(context.modulators.opacityScale, kFollowingContextOpacity);
  EXPECT_LT(evaluate(context, 400).a, evaluate(twoPointTf(300), 400).a);

  workstation.apply(TfChange{TfTarget::context, twoPointTf(-50), ""});
  workstation.apply(TfChange{TfTarget::main, twoPointTf(100), "y"});
  EXPECT_EQ(tfOf(document, TfTarget::focus), twoPointTf(100));
  EXPECT_EQ(tfOf(document, TfTarget::context), twoPointTf(-50));

  workstation.apply(TfChange{TfTarget::context, {}, "", true});
  EXPECT_TRUE(document.vesselGlyph.contextFollowsMain);
  EXPECT_EQ(tfOf(document, TfTarget::context).points, twoPointTf(100).points);
}

TEST(GuiWorkstation, RenderingEditsKeepTheMipWindowInTheMainTf) {
  Workstation workstation;
  RenderingEdit edit;
  edit.mode = Compositing::mip;
  edit.mipWindow = 1500;
  edit.mipLevel = 500;
  workstation.apply(edit);
  EXPECT_EQ(workstation.document().mode, Compositing::mip);
  EXPECT_DOUBLE_EQ(workstation.document().tf.mipWindow, 1500);
  EXPECT_DOUBLE_EQ(workstation.document().tf.mipLevel, 500);
}

TEST(GuiWorkstation, ALoadedCenterlineFileIsRecordedAndNothingElseChanges) {
  Document start;
  start.vesselGlyph.enabled = true;
  start.vesselGlyph.settings.cleft = true;
  Workstation workstation(start);
  workstation.apply(CenterlineFileEdit{"c.csv", "/data/c.csv"});
  Document expected = start;
  expected.vesselGlyph.centerlines = "c.csv";
  expected.vesselGlyph.centerlinesAbsolute = "/data/c.csv";
  EXPECT_EQ(workstation.document(), expected);
  workstation.apply(
      CenterlineFileEdit{});  // `gui --centerlines`: the session's file is not the one shown
  EXPECT_EQ(workstation.document(), start);
}

TEST(GuiWorkstation, TheCprPaneFitsAgainForAnotherImageAndKeepsItsZoomForTheRest) {
  Document start;
  start.cpr.shown = true;
  Workstation workstation(start);
  CprState zoomed = start.cpr;
  zoomed.zoom = 3;
  zoomed.panPx = {40, -20};
  workstation.apply(CprEdit{zoomed});
  CprState windowed = zoomed;
  windowed.window = {300, 100};  // the same image, another window: the zoom stays
  workstation.apply(CprEdit{windowed});
  EXPECT_EQ(workstation.document().cpr, windowed);
  for (const auto& another : {+[](CprState& c) { c.path = 2; }, +[](CprState& c) { c.widthMm = 30; },
                              +[](CprState& c) { c.mode = CprMode::stretched; }}) {
    workstation.apply(CprEdit{zoomed});
    CprState edited = zoomed;
    another(edited);
    workstation.apply(CprEdit{edited});
    EXPECT_EQ(workstation.document().cpr.zoom, 1);
    EXPECT_EQ(workstation.document().cpr.panPx, glm::dvec2(0.0));
  }
  workstation.apply(CprEdit{zoomed});
  workstation.apply(CenterlineFileEdit{"c.csv", "/data/c.csv"});
  EXPECT_EQ(workstation.document().cpr.zoom, 1);
  workstation.apply(CprEdit{zoomed});
  workstation.apply(DatasetOpened{"/data/b.mha"});
  EXPECT_EQ(workstation.document().cpr.zoom, 1);
}

TEST(GuiWorkstation, LabelStylesLiveInTheMainTfAndAPresetWithoutLabelsKeepsThem) {
  Workstation workstation;
  const std::vector<LabelStyle> styles = {{1, "bone", LabelMode::hidden, {}, {1, 1, 1}}};
  workstation.apply(LabelStylesEdit{styles, true});
  EXPECT_EQ(workstation.document().tf.labels, styles);
  EXPECT_TRUE(workstation.document().labels.showRemoved);
  // A preset (no labels) replaces the points, not the labels: removed bone stays removed.
  workstation.apply(TfChange{TfTarget::main, twoPointTf(200), "cta-vessels"});
  EXPECT_EQ(workstation.document().tf.points, twoPointTf(200).points);
  EXPECT_EQ(workstation.document().tf.labels, styles);
  // A TF file with labels brings its own.
  TransferFunction withLabels = twoPointTf(300);
  withLabels.labels = {{3, "kidney", LabelMode::tf, twoPointTf(0).points, {0, 1, 0}}};
  workstation.apply(TfChange{TfTarget::main, withLabels, ""});
  EXPECT_EQ(workstation.document().tf.labels, withLabels.labels);
}

TEST(GuiWorkstation, ANewDatasetDropsTheOldLabelFile) {
  Workstation workstation;
  workstation.apply(LabelFileEdit{"/data/a-labels.seg.nrrd"});
  EXPECT_EQ(workstation.document().labels.file, "/data/a-labels.seg.nrrd");
  workstation.apply(DatasetOpened{"/data/b.nrrd"});
  EXPECT_EQ(workstation.document().labels.file, "");
}

TEST(GuiWorkstation, EachTfTargetKeepsItsOwnUndoStack) {
  TfTargets targets;
  EXPECT_EQ(targets.editing(), TfTarget::main);
  targets.history().push(twoPointTf(0));
  targets.edit(TfTarget::focus);
  EXPECT_FALSE(targets.history().canUndo());
  targets.history().push(twoPointTf(300));
  targets.edit(TfTarget::main);
  ASSERT_TRUE(targets.history().canUndo());
  EXPECT_EQ(targets.history().undo(twoPointTf(50)), twoPointTf(0));
  targets.edit(TfTarget::focus);
  EXPECT_EQ(targets.history().undo(twoPointTf(50)), twoPointTf(300));
}

}  // namespace
}  // namespace angio

namespace angio {
namespace {

VesselPath tracedPath(const std::string& name) {
  return {name, {{1, 2, 3}, {4, 5, 6}}, {name, {{{1, 2, 3}, 1.5}, {{4, 5, 6}, 1.2}}}};
}

TEST(GuiWorkstation, VesselPathEditsMarkThemUnsavedAndBumpTheirRevisionOnlyWhenTheyChange) {
  Workstation workstation;
  workstation.apply(VesselPathsEdit{{tracedPath("path 1")}});
  EXPECT_TRUE(workstation.document().vessels.unsaved);
  const std::uint64_t revision = workstation.document().vessels.revision;
  const std::uint64_t version = workstation.version();
  workstation.apply(VesselPathsEdit{{tracedPath("path 1")}});  // the same paths: no change
  EXPECT_EQ(workstation.document().vessels.revision, revision);
  EXPECT_EQ(workstation.version(), version);
  workstation.apply(VesselFileEdit{workstation.document().vessels.paths, "/data/v.csv"});
  EXPECT_FALSE(workstation.document().vessels.unsaved);
  EXPECT_EQ(workstation.document().vessels.file, "/data/v.csv");
  EXPECT_EQ(workstation.document().vessels.revision, revision);  // saved, not changed
  EXPECT_EQ(centerlinesOf(workstation.document().vessels).paths.size(), 1u);
}

TEST(GuiWorkstation, ANewDatasetDropsTheVesselPathsAndASessionBringsItsOwn) {
  Workstation workstation;
  workstation.apply(VesselFileEdit{{tracedPath("a"), tracedPath("b")}, "/data/v.csv"});
  const std::uint64_t revision = workstation.document().vessels.revision;
  workstation.apply(DatasetOpened{"/data/other.mha"});
  EXPECT_TRUE(workstation.document().vessels.paths.empty());
  EXPECT_TRUE(workstation.document().vessels.file.empty());
  EXPECT_GT(workstation.document().vessels.revision, revision);
  Document session;
  session.vessels.paths = {tracedPath("c")};
  session.vessels.unsaved = true;
  workstation.apply(SessionEdit{session});
  ASSERT_EQ(workstation.document().vessels.paths.size(), 1u);
  EXPECT_EQ(workstation.document().vessels.paths[0].name, "c");
  EXPECT_TRUE(workstation.document().vessels.unsaved);
  EXPECT_GT(workstation.document().vessels.revision, revision + 1);
}

TEST(GuiWorkstation, PathsWithFewerThanTwoPointsAreNotCenterlines) {
  VesselsState vessels;
  vessels.paths = {{"one click", {{1, 2, 3}}, {"one click", {}}}, tracedPath("two")};
  const Centerlines centerlines = centerlinesOf(vessels);
  ASSERT_EQ(centerlines.paths.size(), 1u);
  EXPECT_EQ(centerlines.paths[0].name, "two");
  EXPECT_EQ(centerlines.frame, CenterlineFrame::physical);
}

}  // namespace
}  // namespace angio
