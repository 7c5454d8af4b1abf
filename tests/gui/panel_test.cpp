// The side panel's sections as functions: drawn in an ImGui context with no window or renderer
// behind it, driven by mouse input over a few frames; what they return is checked, and applied.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include <imgui.h>

#include "gui/panel_cpr.h"
#include "gui/panel_data.h"
#include "gui/panel_export.h"
#include "gui/panel_rendering.h"
#include "gui/panel_session.h"
#include "gui/panel_tf.h"
#include "gui/panel_vessels.h"
#include "gui/panel_vessel_glyph.h"
#include "gui/panel_view.h"
#include "gui/tf_editor.h"
#include "gui/viewport.h"
#include "gui/workstation.h"
#include "io/tf_file.h"

namespace angio {
namespace {

// An ImGui context of its own per test: one window filling the display, frames 1/60 s apart.
class GuiPanels : public ::testing::Test {
 protected:
  void SetUp() override {
    context_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(kWidth, kHeight);
    io.DeltaTime = 1.f / 60;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  }
  void TearDown() override { ImGui::DestroyContext(context_); }

  // One frame with the mouse at `mouse`, the left button as given; returns what `draw` returned.
  template <class Draw>
  auto frame(Draw draw, ImVec2 mouse = ImVec2(-1, -1), bool leftDown = false) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = mouse;
    io.MouseDown[0] = leftDown;
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(io.DisplaySize);
    ImGui::Begin("panel", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
    auto result = draw();
    ImGui::End();
    ImGui::Render();
    return result;
  }

  // A click at `at`: hover, press, release; returns what `draw` returned on the release frame.
  template <class Draw>
  auto click(Draw draw, ImVec2 at) {
    frame(draw, at, false);
    frame(draw, at, true);
    return frame(draw, at, false);
  }

  // Ctrl+click at `at` (a slider takes typed text then, all of it selected) and types `text`;
  // returns the last edit `draw` returned.
  template <class Draw>
  auto typeInto(Draw draw, ImVec2 at, const std::string& text) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = true;
    decltype(draw()) edit = frame(draw, at);
    frame(draw, at, true);
    frame(draw, at, false);
    io.KeyCtrl = false;
    for (const char c : text) {
      io.AddInputCharacter(static_cast<unsigned char>(c));
      if (auto typed = frame(draw, at)) edit = typed;
    }
    return edit;
  }

  // Where the next widget would go after `draw`: what sits below a section does not move while
  // this stays the same.
  template <class Draw>
  float bottomAfter(Draw draw) {
    float bottom = 0;
    frame([&] {
      draw();
      bottom = ImGui::GetCursorPosY();
      return 0;
    });
    return bottom;
  }

  static ImVec2 centre(const std::pair<ImVec2, ImVec2>& rect) {
    return ImVec2((rect.first.x + rect.second.x) / 2, (rect.first.y + rect.second.y) / 2);
  }
  // The centre of the n-th row of widgets (from 0) of a panel drawn at the window's top.
  static float rowCentreY(int row) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float height = ImGui::GetIO().Fonts->Fonts[0]->FontSize + 2 * style.FramePadding.y;
    return style.WindowPadding.y + row * (height + style.ItemSpacing.y) + height / 2;
  }

  static constexpr float kWidth = 430, kHeight = 800;
  ImGuiContext* context_ = nullptr;
};

Centerlines twoPaths() {
  Centerlines centerlines;
  for (int p = 0; p < 2; ++p) {
    CenterlinePath path;
    path.name = p ? "left" : "right";
    for (int n = 0; n < 3; ++n) path.points.push_back({glm::dvec3(p * 10.0, n * 5.0, 0.0), 2.0});
    centerlines.paths.push_back(path);
  }
  return centerlines;
}

TEST_F(GuiPanels, WithoutInputNoPanelReturnsAnEdit) {
  const Document document;
  const Centerlines centerlines = twoPaths();
  WidgetRects rects;
  VesselGlyphPanelUi ui;
  VesselGlyphPanelInfo vg;
  vg.physical = &centerlines;
  for (int n = 0; n < 3; ++n) {
    EXPECT_FALSE(frame([&] { return drawViewPanel(document.view); }));
    EXPECT_FALSE(frame([&] { return drawRenderingPanel(document); }));
    EXPECT_FALSE(frame([&] {
      return drawCprPanel(document.cpr, {&centerlines, false, "", ""}, rects);
    }));
    const VesselGlyphPanelResult result =
        frame([&] { return drawVesselGlyphPanel(document.vesselGlyph, ui, vg, rects); });
    EXPECT_FALSE(result.edit);
    EXPECT_FALSE(result.loadCenterlines);
  }
}

TEST_F(GuiPanels, ClickingTheHybridCheckboxReturnsAnEditThatTurnsVesselGlyphOn) {
  Workstation workstation;
  const Centerlines centerlines = twoPaths();
  WidgetRects rects;
  const auto draw = [&] {
    const CprPanelInfo info{&centerlines, workstation.document().vesselGlyph.enabled, "", ""};
    return drawCprPanel(workstation.document().cpr, info, rects);
  };
  frame(draw);
  ASSERT_TRUE(rects.count("cpr_hybrid"));
  const std::optional<CprEdit> edit = click(draw, centre(rects["cpr_hybrid"]));
  ASSERT_TRUE(edit);
  EXPECT_TRUE(edit->cpr.hybrid);
  EXPECT_FALSE(edit->cpr.shown);  // only what was clicked
  ASSERT_FALSE(workstation.document().vesselGlyph.enabled);
  workstation.apply(*edit);
  EXPECT_TRUE(workstation.document().cpr.hybrid);
  EXPECT_TRUE(workstation.document().vesselGlyph.enabled);
  EXPECT_EQ(workstation.version(), 1u);
}

TEST_F(GuiPanels, TheAngleSliderAtItsEndGives360WhichApplyWrapsToZero) {
  Workstation workstation;
  ViewState turned = workstation.document().view;
  turned.angleDeg = 90;
  workstation.apply(ViewEdit{turned});
  const auto draw = [&] { return drawViewPanel(workstation.document().view); };
  // Row 1 is the angle slider, ending 80 pixels short of the content's right edge: press just
  // inside its end.
  const float sliderEnd = kWidth - ImGui::GetStyle().WindowPadding.x - 80;
  const ImVec2 end(sliderEnd - 4, rowCentreY(1));
  frame(draw, end);
  const std::optional<ViewEdit> edit = frame(draw, end, true);
  ASSERT_TRUE(edit);
  EXPECT_DOUBLE_EQ(edit->view.angleDeg, 360);
  EXPECT_EQ(edit->view.axis, turned.axis);
  workstation.apply(*edit);
  EXPECT_DOUBLE_EQ(workstation.document().view.angleDeg, 0);
}

TEST_F(GuiPanels, TheMipCheckboxSwitchesToMipKeepingTheWindow) {
  Document document;
  const auto draw = [&] { return drawRenderingPanel(document); };
  const ImVec2 checkbox(ImGui::GetStyle().WindowPadding.x + 8, rowCentreY(0));
  const std::optional<RenderingEdit> edit = click(draw, checkbox);
  ASSERT_TRUE(edit);
  EXPECT_EQ(edit->mode, Compositing::mip);
  EXPECT_DOUBLE_EQ(edit->mipWindow, document.tf.mipWindow);
  EXPECT_EQ(edit->shading, document.shading);
}

// A value typed into a slider (Ctrl+click) stays within the slider's range: a MIP window of 0 or
// a level far beyond the density scale never reaches the document (rows 1 and 2 in MIP mode).
TEST_F(GuiPanels, ValuesTypedIntoSlidersAreClampedToTheirRange) {
  Document document;
  document.mode = Compositing::mip;
  const auto draw = [&] { return drawRenderingPanel(document); };
  const float x = ImGui::GetStyle().WindowPadding.x + 100;
  const std::optional<RenderingEdit> window = typeInto(draw, ImVec2(x, rowCentreY(1)), "0");
  ASSERT_TRUE(window);
  EXPECT_DOUBLE_EQ(window->mipWindow, 1);
  const std::optional<RenderingEdit> level = typeInto(draw, ImVec2(x, rowCentreY(2)), "99999");
  ASSERT_TRUE(level);
  EXPECT_DOUBLE_EQ(level->mipLevel, 3071);
  EXPECT_DOUBLE_EQ(level->mipWindow, document.tf.mipWindow);
}

// Row 2 (under MIP and shading): pre-integrated classification, for every level at once.
TEST_F(GuiPanels, ThePreintegratedCheckboxSwitchesEveryLevel) {
  Workstation workstation;
  const auto draw = [&] { return drawRenderingPanel(workstation.document()); };
  const ImVec2 checkbox(ImGui::GetStyle().WindowPadding.x + 8, rowCentreY(2));
  const std::optional<RenderingEdit> edit = click(draw, checkbox);
  ASSERT_TRUE(edit);
  EXPECT_TRUE(edit->preintegrated);
  EXPECT_EQ(edit->mode, Compositing::dvr);
  workstation.apply(*edit);
  for (const Sampling& level : workstation.document().levels) EXPECT_TRUE(level.preintegrated);
  EXPECT_TRUE(levelsPreintegrated(workstation.document()));
  const std::optional<RenderingEdit> off = click(draw, checkbox);
  ASSERT_TRUE(off);
  workstation.apply(*off);
  for (const Sampling& level : workstation.document().levels) EXPECT_FALSE(level.preintegrated);
}

// Row 2, after "pre-integrated" and its "(?)": where rays are sampled, a choice of every sample,
// adaptive integration and adaptive sampling, each with its defaults, for every level; choosing
// one drops the other.
TEST_F(GuiPanels, TheAlongRaysChoiceSwitchesEveryLevelToOneAdaptiveScheme) {
  Workstation workstation;
  float afterPreintegrated = 0, line = 0;  // measured while drawing, when the font is set
  const auto draw = [&] {
    const ImGuiStyle& style = ImGui::GetStyle();
    afterPreintegrated = style.WindowPadding.x + ImGui::GetFrameHeight() + style.ItemInnerSpacing.x +
                         ImGui::CalcTextSize("pre-integrated").x + style.ItemSpacing.x +
                         ImGui::CalcTextSize("(?)").x + style.ItemSpacing.x;
    line = ImGui::GetTextLineHeightWithSpacing();
    return drawRenderingPanel(workstation.document());
  };
  frame(draw);
  const ImVec2 combo(afterPreintegrated + 20, rowCentreY(2));
  // The popup lists the choices under the combo, one text line each.
  const auto choose = [&](int item) {
    EXPECT_FALSE(click(draw, combo));  // opens the list
    const float top = rowCentreY(2) + ImGui::GetFrameHeight() / 2 + ImGui::GetStyle().WindowPadding.y;
    return click(draw, ImVec2(combo.x, top + (item + 0.5f) * line));
  };
  const std::optional<RenderingEdit> integrating = choose(1);
  ASSERT_TRUE(integrating);
  ASSERT_TRUE(integrating->adaptive);
  EXPECT_EQ(*integrating->adaptive, AdaptiveIntegration{});
  EXPECT_FALSE(integrating->adaptiveSampling);
  workstation.apply(*integrating);
  for (const Sampling& level : workstation.document().levels)
    EXPECT_EQ(level.adaptive, integrating->adaptive);

  const std::optional<RenderingEdit> sampling = choose(2);
  ASSERT_TRUE(sampling);
  EXPECT_FALSE(sampling->adaptive);
  ASSERT_TRUE(sampling->adaptiveSampling);
  EXPECT_EQ(*sampling->adaptiveSampling, AdaptiveSampling{});
  workstation.apply(*sampling);
  for (const Sampling& level : workstation.document().levels) {
    EXPECT_FALSE(level.adaptive);
    EXPECT_EQ(level.adaptiveSampling, sampling->adaptiveSampling);
  }

  const std::optional<RenderingEdit> exact = choose(0);
  ASSERT_TRUE(exact);
  EXPECT_FALSE(exact->adaptive);
  EXPECT_FALSE(exact->adaptiveSampling);
}

TEST_F(GuiPanels, TheVesselGlyphPanelAsksForItsFileAndTurnsVesselGlyphOn) {
  Workstation workstation;
  const Centerlines centerlines = twoPaths();
  WidgetRects rects;
  VesselGlyphPanelUi ui;
  VesselGlyphPanelInfo info;
  const auto draw = [&] {
    return drawVesselGlyphPanel(workstation.document().vesselGlyph, ui, info, rects);
  };
  frame(draw);
  EXPECT_FALSE(rects.count("vg_enable"));  // nothing loaded: only the file field and the button
  ASSERT_TRUE(rects.count("vg_load"));
  EXPECT_TRUE(click(draw, centre(rects["vg_load"])).loadCenterlines);

  info.physical = &centerlines;
  frame(draw);
  ASSERT_TRUE(rects.count("vg_enable"));
  const VesselGlyphPanelResult result = click(draw, centre(rects["vg_enable"]));
  EXPECT_FALSE(result.loadCenterlines);
  ASSERT_TRUE(result.edit);
  workstation.apply(*result.edit);
  EXPECT_TRUE(workstation.document().vesselGlyph.enabled);
  EXPECT_EQ(workstation.document().vesselGlyph.settings, VesselGlyphSettings{});
}

TEST_F(GuiPanels, TheViewportZoomsWithTheWheelAndTurnsWithALeftDrag) {
  const ViewState view;
  const ViewportOverlay overlay;
  const ImVec2 middle(kWidth / 2, kHeight / 2);
  frame([&] { return drawViewport(nullptr, view, overlay); }, middle);
  ImGui::GetIO().MouseWheel = 1;
  const ViewportInteraction zoomed = frame([&] { return drawViewport(nullptr, view, overlay); }, middle);
  ImGui::GetIO().MouseWheel = 0;
  ASSERT_TRUE(zoomed.zoomedOrPanned);
  EXPECT_NEAR(zoomed.zoomedOrPanned->zoom, 1.2, 1e-9);
  EXPECT_EQ(zoomed.rotateDegrees, 0);

  frame([&] { return drawViewport(nullptr, view, overlay); }, middle, true);
  const ImVec2 right(middle.x + 10, middle.y);
  const ViewportInteraction turned =
      frame([&] { return drawViewport(nullptr, view, overlay); }, right, true);
  EXPECT_DOUBLE_EQ(turned.rotateDegrees, -10 * view.degreesPerPixel);  // grab: the front moves right
  EXPECT_FALSE(turned.zoomedOrPanned);
}

TEST(GuiTfEditor, ADragMovesAnAxisOnlyOnceThePointerLeftItsDeadZone) {
  TfPointDrag drag{{100, 100}, 200, 0.5};
  const double huPerPx = 10, opacityPerPx = 0.01;
  // Sideways with a pixel of slip: the HU follows, the opacity stays.
  EXPECT_EQ(followDrag(drag, {140, 101}, false, huPerPx, opacityPerPx), (HuOpacity{600, 0.5}));
  // Past the dead zone vertically too: from then on both follow, even back inside it.
  EXPECT_EQ(followDrag(drag, {140, 90}, false, huPerPx, opacityPerPx).opacity, 0.5 + 10 * 0.01);
  EXPECT_DOUBLE_EQ(followDrag(drag, {140, 99}, false, huPerPx, opacityPerPx).opacity, 0.51);
  // Within the dead zone on both axes nothing moves.
  TfPointDrag still{{100, 100}, 200, 0.5};
  EXPECT_EQ(followDrag(still, {103, 97}, false, huPerPx, opacityPerPx), (HuOpacity{200, 0.5}));
  // Shift: the dominant axis only.
  TfPointDrag shifted{{100, 100}, 200, 0.5};
  EXPECT_EQ(followDrag(shifted, {130, 80}, true, huPerPx, opacityPerPx), (HuOpacity{500, 0.5}));
  EXPECT_EQ(followDrag(shifted, {110, 60}, true, huPerPx, opacityPerPx), (HuOpacity{200, 0.9}));
}

TEST(GuiTfEditor, HuTicksAreRoundAndZeroIsNeverNegative) {
  const std::vector<HuTick> ticks = huTicks(-100, 1000);
  ASSERT_FALSE(ticks.empty());
  for (const HuTick& tick : ticks) {
    EXPECT_NE(tick.label, "-0");
    EXPECT_GE(tick.hu, -100);
    EXPECT_LE(tick.hu, 1000);
  }
  EXPECT_EQ(ticks.front().label, "0");
  EXPECT_EQ(huTicks(-1024, 3071).front().label, "-1000");
  EXPECT_EQ(huTicks(-1024, 3071).size(), 5u);  // every 1000 HU
}

// The TF editor's plot, drawn alone: a two-point ramp, the plot's default HU range.
class GuiTfEditorPlot : public GuiPanels {
 protected:
  GuiTfEditorPlot() {
    tf.points = {ControlPoint{0, glm::vec3(1), 0.2}, ControlPoint{1000, glm::vec3(1), 0.6}};
  }
  TfEdit draw(ImVec2 mouse = ImVec2(-1, -1), bool down = false) {
    return frame([&] { return drawTfEditor(tf, {}, view); }, mouse, down);
  }
  ImVec2 pointOnScreen(const ControlPoint& point) const {
    const float width = view.plotMax.x - view.plotMin.x, height = view.plotMax.y - view.plotMin.y;
    return ImVec2(view.plotMin.x + float((point.hu - view.huMin) / (view.huMax - view.huMin)) * width,
                  view.plotMax.y - float(point.opacity) * height);
  }
  TransferFunction tf;
  TfEditorView view;
};

TEST_F(GuiTfEditorPlot, ASidewaysDragWithAPixelOfSlipKeepsTheOpacity) {
  draw();
  const ImVec2 at = pointOnScreen(tf.points[1]);
  draw(at);
  draw(at, true);
  TfEdit edit;
  for (int step = 1; step <= 8; ++step) {
    edit = draw(ImVec2(at.x + 5.f * step, at.y + (step % 2 ? 1.f : -1.f)), true);
    if (edit.changed) tf = edit.tf;
  }
  const double huPerPx = (view.huMax - view.huMin) / (view.plotMax.x - view.plotMin.x);
  EXPECT_DOUBLE_EQ(tf.points[1].opacity, 0.6);
  EXPECT_NEAR(tf.points[1].hu, 1000 + 40 * huPerPx, 0.51);
}

TEST_F(GuiTfEditorPlot, ThePlainWheelLeavesTheHuRangeAndCtrlWheelZoomsIt) {
  draw();
  const ImVec2 middle((view.plotMin.x + view.plotMax.x) / 2, (view.plotMin.y + view.plotMax.y) / 2);
  draw(middle);
  const TfEditorView before = view;
  ImGui::GetIO().MouseWheel = 2;
  draw(middle);
  EXPECT_EQ(view.huMin, before.huMin);
  EXPECT_EQ(view.huMax, before.huMax);
  ImGui::GetIO().MouseWheel = 2;
  ImGui::GetIO().KeyCtrl = true;
  draw(middle);
  ImGui::GetIO().KeyCtrl = false;
  EXPECT_LT(view.huMax - view.huMin, 0.7 * (before.huMax - before.huMin));
}

TEST_F(GuiPanels, TheTfSectionOffersTheRegionTfsOnlyWhenAskedAndSwitchesOnAClick) {
  Document document;
  TfPanelUi ui;
  TfPanelInfo info;
  WidgetRects rects;
  const auto draw = [&] { return drawTfPanel(document, ui, info, rects); };
  for (int n = 0; n < 3; ++n) {
    const TfPanelRequests idle = frame(draw);
    EXPECT_FALSE(idle.switchTo || idle.replace || idle.edit || idle.committedBefore);
    EXPECT_FALSE(idle.undo || idle.redo || idle.save);
  }
  EXPECT_FALSE(rects.count("vg_edit_focus"));
  info.targetsShown = true;
  frame(draw);
  ASSERT_TRUE(rects.count("vg_edit_focus"));
  const TfPanelRequests clicked = click(draw, centre(rects["vg_edit_focus"]));
  ASSERT_TRUE(clicked.switchTo);
  EXPECT_EQ(*clicked.switchTo, TfTarget::focus);
  EXPECT_FALSE(clicked.edit);
}

TEST_F(GuiPanels, TheTfSectionLoadsAMissingFileAsAMessageNotAnEdit) {
  Document document;
  TfPanelUi ui;
  ui.path = "/nonexistent/tf.json";
  TfPanelInfo info;
  WidgetRects rects;
  const auto draw = [&] { return drawTfPanel(document, ui, info, rects); };
  frame(draw);
  ASSERT_TRUE(rects.count("tf_load"));
  const TfPanelRequests loaded = click(draw, centre(rects["tf_load"]));
  EXPECT_FALSE(loaded.replace);
  EXPECT_NE(loaded.message.find("/nonexistent/tf.json"), std::string::npos) << loaded.message;
}

TEST_F(GuiPanels, ATfLoadedFromAFileIsNamedByTheFileNotAsEdited) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("angioray-tf-" + std::to_string(::getpid()) + ".json");
  TransferFunction saved;
  saved.name = "mine";
  saved.points = {ControlPoint{100, glm::vec3(1), 0.5}};
  saveTransferFunction(saved, file.string());
  Document document;
  TfPanelUi ui;
  ui.path = file.string();
  TfPanelInfo info;
  WidgetRects rects;
  const auto draw = [&] { return drawTfPanel(document, ui, info, rects); };
  frame(draw);
  const TfPanelRequests loaded = click(draw, centre(rects["tf_load"]));
  std::filesystem::remove(file);
  ASSERT_TRUE(loaded.replace) << loaded.message;
  EXPECT_EQ(loaded.replace->preset, file.string());  // not "" (edited)
  EXPECT_EQ(loaded.replace->tf.points, saved.points);
}

TEST_F(GuiPanels, TheSessionSectionAsksToSaveOrLoad) {
  SessionPanelUi ui;
  WidgetRects rects;
  const auto draw = [&] { return drawSessionPanel(ui, rects); };
  frame(draw);
  const SessionPanelRequests save = click(draw, centre(rects["session_save"]));
  EXPECT_TRUE(save.save);
  EXPECT_FALSE(save.load);
  const SessionPanelRequests load = click(draw, centre(rects["session_load"]));
  EXPECT_TRUE(load.load);
  EXPECT_FALSE(load.save);
}

TEST_F(GuiPanels, TheDataSectionAsksToBrowseAndToDismissALoadError) {
  const Document document;
  DataPanelInfo info;
  info.name = "phantom 8x8x8";
  WidgetRects rects;
  const auto draw = [&] { return drawDataPanel(document, info, rects); };
  frame(draw);
  EXPECT_FALSE(rects.count("data_dismiss"));
  EXPECT_TRUE(click(draw, centre(rects["data_open"])).browse);
  info.loadError = "broken.mha: not a volume";
  frame(draw);
  ASSERT_TRUE(rects.count("data_dismiss"));
  const DataPanelRequests dismissed = click(draw, centre(rects["data_dismiss"]));
  EXPECT_TRUE(dismissed.dismissError);
  EXPECT_FALSE(dismissed.browse || dismissed.cancelLoad || dismissed.open);
}

TEST_F(GuiPanels, TheExportSectionStartsAJobUnlessOneIsRunning) {
  ExportPanelUi ui;
  SeriesPanel series;
  JobInfo job;
  WidgetRects rects;
  const auto draw = [&] {
    const ExportRequests image = drawImageExport(ui, job, rects);
    const ExportRequests rotation = drawSeriesExport(series, job, rects);
    return std::make_pair(image, rotation);
  };
  frame(draw);
  ASSERT_TRUE(rects.count("export_button") && rects.count("series_button"));
  const auto image = click(draw, centre(rects["export_button"]));
  EXPECT_TRUE(image.first.start);
  EXPECT_FALSE(image.second.start);
  const auto rotation = click(draw, centre(rects["series_button"]));
  EXPECT_TRUE(rotation.second.start);
  EXPECT_FALSE(rotation.first.start);

  job.running = true;
  rects.clear();
  frame(draw);
  EXPECT_FALSE(rects.count("export_button"));
  ASSERT_TRUE(rects.count("series_cancel"));
  EXPECT_TRUE(click(draw, centre(rects["series_cancel"])).second.cancel);
}

TEST_F(GuiPanels, ThePressOfADragDoesNotTurnByThePointersJumpToIt) {
  const ViewState view;
  const ViewportOverlay overlay;
  const auto draw = [&] { return drawViewport(nullptr, view, overlay); };
  frame(draw, ImVec2(20, 20));
  // Warped and pressed in one event batch (a remote desktop): one frame, 200 px from the last.
  const ImVec2 pressed(220, 300);
  const ViewportInteraction press = frame(draw, pressed, true);
  EXPECT_EQ(press.rotateDegrees, 0);
  const ViewportInteraction dragged = frame(draw, ImVec2(pressed.x + 40, pressed.y), true);
  EXPECT_DOUBLE_EQ(dragged.rotateDegrees, -40 * view.degreesPerPixel);
}

TEST_F(GuiPanels, AnExportOverAnExistingFileAsksFirstInTheButtonsRow) {
  const std::filesystem::path existing = std::filesystem::temp_directory_path() /
                                         ("angioray-exists-" + std::to_string(::getpid()) + ".png");
  std::ofstream(existing) << "the user's image";
  ExportPanelUi ui;
  ui.path = existing.string();
  const JobInfo idle;
  WidgetRects rects;
  const auto draw = [&] { return drawImageExport(ui, idle, rects); };
  const float bottom = bottomAfter(draw);
  const std::pair<ImVec2, ImVec2> button = rects["export_button"];
  EXPECT_FALSE(click(draw, centre(button)).start);  // asks instead
  frame(draw);
  ASSERT_TRUE(rects.count("export_button_keep"));
  EXPECT_EQ(bottomAfter(draw), bottom);  // in the button's row
  EXPECT_FALSE(click(draw, centre(rects["export_button_keep"])).start);
  EXPECT_TRUE(ui.confirmingPath.empty());
  click(draw, centre(button));
  frame(draw);
  EXPECT_TRUE(click(draw, centre(rects["export_button_overwrite"])).start);
  std::filesystem::remove(existing);
  EXPECT_TRUE(click(draw, centre(button)).start);  // nothing there: no question
}

TEST_F(GuiPanels, ADoubleClickOnTheViewportResetsZoomAndPan) {
  ViewState view;
  view.zoom = 4;
  view.panPx = {30, -12};
  const ViewportOverlay overlay;
  const ImVec2 middle(kWidth / 2, kHeight / 2);
  const auto draw = [&] { return drawViewport(nullptr, view, overlay); };
  EXPECT_FALSE(click(draw, middle).reset);
  // The second press, within the double-click time, is the double-click.
  const ViewportInteraction reset = frame(draw, middle, true);
  EXPECT_TRUE(reset.reset);
  ASSERT_TRUE(reset.zoomedOrPanned);
  EXPECT_DOUBLE_EQ(reset.zoomedOrPanned->zoom, 1);
  EXPECT_EQ(reset.zoomedOrPanned->panPx, glm::dvec2(0.0));
}

TEST_F(GuiPanels, ALoadItsErrorOrNothingTakeTheSameRowsInTheDataSection) {
  const Document document;
  WidgetRects rects;
  DataPanelInfo info;
  const auto draw = [&] { drawDataPanel(document, info, rects); };
  const float idle = bottomAfter(draw);
  info.loading = true;
  info.loadPath = "/data/a.mha";
  EXPECT_EQ(bottomAfter(draw), idle);
  info.loading = false;
  info.loadError = "/data/a.mha: not a volume, and a long explanation that would not fit on one row";
  EXPECT_EQ(bottomAfter(draw), idle);
}

TEST_F(GuiPanels, TheHybridsControlsAndMessagesDoNotMoveTheRowsBelow) {
  const Centerlines centerlines = twoPaths();
  WidgetRects rects;
  CprState cpr;
  CprPanelInfo info{&centerlines, false, "", ""};
  const auto draw = [&] { drawCprPanel(cpr, info, rects); };
  const float off = bottomAfter(draw);
  cpr.hybrid = true;  // the transition slider, and "needs VesselGlyph on"
  EXPECT_EQ(bottomAfter(draw), off);
  info.vesselGlyphEnabled = true;
  info.hybridProblem = "path 0 lies outside the view";
  info.error = "the CPR view failed";
  EXPECT_EQ(bottomAfter(draw), off);
}

TEST_F(GuiPanels, EveryVesselGlyphContextShapeAndMessageTakesTheSameRows) {
  const Centerlines centerlines = twoPaths();
  WidgetRects rects;
  VesselGlyphPanelUi ui;
  VesselGlyphPanelInfo info;
  info.physical = &centerlines;
  VesselGlyphState state;
  const auto draw = [&] { drawVesselGlyphPanel(state, ui, info, rects); };
  state.settings.context = ContextShape::slab;
  const float slab = bottomAfter(draw);
  state.settings.context = ContextShape::tube;
  EXPECT_EQ(bottomAfter(draw), slab);
  state.settings.context = ContextShape::none;
  EXPECT_EQ(bottomAfter(draw), slab);
  info.error = "could not read b.csv";
  info.warnings = "path 2 has one point";
  info.problem = "no path in the volume";
  EXPECT_EQ(bottomAfter(draw), slab);
  info.loading = true;
  info.loadingFile = "c.csv";
  EXPECT_EQ(bottomAfter(draw), slab);
}

TEST_F(GuiPanels, TheTracersProgressAndTheSectionsErrorsDoNotMoveTheRowsBelow) {
  const VesselsState vessels;
  WidgetRects rects;
  VesselsPanelUi ui;
  ui.traceTool = true;
  VesselsPanelInfo info;
  info.hasVolume = true;
  const auto draw = [&] { drawVesselsPanel(vessels, ui, info, rects); };
  const float idle = bottomAfter(draw);
  info.busy = true;
  info.busyWhat = "lumen field";
  info.queued = 2;
  info.error = "could not write paths.vtp";
  EXPECT_EQ(bottomAfter(draw), idle);
}

TEST_F(GuiPanels, TheLastMovieAndARunningSeriesTakeTheSameRows) {
  SeriesPanel series;
  WidgetRects rects;
  JobInfo job;
  const auto draw = [&] { drawSeriesExport(series, job, rects); };
  const float none = bottomAfter(draw);
  series.movieNote = "series.mp4 (H.264)";
  EXPECT_EQ(bottomAfter(draw), none);
  job.running = true;
  EXPECT_EQ(bottomAfter(draw), none);
}

TEST(GuiViewport, FitViewFillsTheViewportWithTheVolumeAsSeenNow) {
  // The aorta's domain about k: 138 mm wide at 0 deg, 345 mm at 90, hypot 371; 51 mm high.
  const glm::dvec3 extent(138, 345, 51);
  const glm::dvec2 viewport(570, 970);
  const double atZoomOne = std::min(570 / std::hypot(138.0, 345.0), 970 / 51.0);
  EXPECT_NEAR(zoomToFitView(extent, Axis::k, 0, viewport), (570 / 138.0) / atZoomOne, 1e-12);
  EXPECT_NEAR(zoomToFitView(extent, Axis::k, 90, viewport), (570 / 345.0) / atZoomOne, 1e-9);
  // A viewport too short for the height: the height decides, at every angle alike.
  EXPECT_DOUBLE_EQ(zoomToFitView(extent, Axis::k, 0, {5000, 100}), 1);
}

TEST(GuiOrientation, LpsLettersNameTheDominantAxisAndATieGoesToTheEarlierAxis) {
  EXPECT_EQ(lpsLetter({1, 0, 0}), 'L');
  EXPECT_EQ(lpsLetter({-1, 0, 0}), 'R');
  EXPECT_EQ(lpsLetter({0.1, -0.9, 0.2}), 'A');
  EXPECT_EQ(lpsLetter({0, 0.3, -0.8}), 'I');
  EXPECT_EQ(lpsLetter({0.7071, 0.7071, 0}), 'L');
  EXPECT_EQ(lpsLetter({0, -0.5, 0.5}), 'A');
  const OrientationLetters front = orientationLetters(Axis::k, 0);
  EXPECT_EQ(std::string({front.right, front.left, front.top, front.bottom}), "LRSI");
}

}  // namespace
}  // namespace angio
