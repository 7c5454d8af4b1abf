#pragma once
// The workstation app: one ImGui frame at a time, shared by the GLFW window and the OSMesa twin.
// The platform calls its backend's NewFrame, then App::frame() (ImGui::NewFrame .. ImGui::Render),
// then renders ImGui's draw data. Rendering happens in the ProgressiveRenderer's thread; the UI
// thread only swaps in finished frames and uploads them as a texture, so it never waits.
#include <atomic>
#include <chrono>
#include <deque>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/motion_sampling.h"
#include "render/progressive_renderer.h"
#include "core/ray_pick.h"
#include "core/slice_tiles.h"
#include "core/volume.h"
#include "io/study_info.h"
#include "io/volume_reader.h"
#include "gui/app_gl.h"
#include "gui/background_job.h"
#include "gui/file_browser.h"
#include "gui/latency_trace.h"
#include "render/series_export.h"
#include "gui/app_cpr.h"
#include "gui/cpr_pane.h"
#include "gui/crop_handles.h"
#include "gui/app_export.h"
#include "gui/app_labels.h"
#include "gui/app_slices.h"
#include "gui/app_vessel.h"
#include "gui/app_vessels.h"
#include "gui/panel_export.h"
#include "gui/panel_session.h"
#include "gui/panel_tf.h"
#include "gui/panel_widgets.h"
#include "gui/session_file.h"
#include "gui/tf_editor.h"
#include "gui/tf_targets.h"
#include "gui/viewport.h"
#include "gui/zoomed_rendering.h"
#include "gui/workstation.h"
#include "render/recipe_json.h"
#include "io/tf_file.h"

namespace angio {

struct LoadedDataset {
  Volume volume;
  std::string name;         // file or folder, or "phantom IxJxK"
  std::string description;  // e.g. "MetaImage float32"
  StudyInfo study;          // the patient and study of a DICOM series
  // The volume's slice tiles for the axis the view starts with, built as part of the load so that
  // the first frame is as interruptible as any (none: the renderer builds them itself); after a
  // label change, those of the renderer before it with the slices it touched stale. Handed to the
  // next renderer.
  TilesAhead tiles;
};

// A volume read from `name` (a file or a DICOM folder) as the app holds it.
LoadedDataset loadedDataset(LoadedVolume loaded, const std::string& name);

// What the app starts with: the document, and what only this run needs.
struct AppStart {
  Document document;
  std::string centerlinesFile;  // centerlines to load at start (`gui --centerlines`), if any
  std::string labelsFile;       // labels to read at start (`gui --labels`; else the session's)
  double motionBudgetMs = 40;   // render/motion_sampling.h (0: the fast level as it is)
};

// UI frame times (ms, as the platform measured them: the window's exclude the buffer swap, the
// headless twin's include software rasterisation), overall and while high renders.
struct FrameTimes {
  struct Stats {
    int frames = 0;
    double sumMs = 0, maxMs = 0;
    void add(double ms);
    double meanMs() const { return frames ? sumMs / frames : 0; }
  };
  Stats all, whileHigh;
};

// How soon the platform should draw the next frame.
enum class FramePacing {
  continuous,  // input, animation or an upload in progress: every display frame
  progress,    // a render is running: now and then for the progress bar (a frame wakes it)
  idle,        // nothing changes without input
};

class App {
 public:
  // `wakeUi` (optional, any thread) makes the platform's event wait return: called when the
  // renderer publishes a frame or goes idle.
  // `threads` (the renderer's arenas and priorities, made once by the program) must outlive it.
  App(LoadedDataset dataset, AppStart start, const GlApi& gl, RenderThreads& threads,
      std::function<void()> wakeUi = {});
  ~App();
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  // One UI frame: ImGui::NewFrame() .. ImGui::Render(). `previousFrameMs` is how long the platform
  // took for the previous frame in all (app, ImGui rendering, buffer swap).
  void frame(double previousFrameMs);
  // The platform presented the frame (after the buffer swap; headless: after glFinish).
  void framePresented();

  // True once the newest request's frame at `level` (or better) is on screen, or the renderer has
  // finished that request without reaching it (interactive requests stop at fast).
  bool settled(Quality level) const;
  bool wantsToQuit() const { return quit_; }
  FramePacing pacing() const;

  // State and runtime numbers for --state-out and the tests.
  nlohmann::json report() const;

  // Loads in the background and replaces the dataset on success (drag-and-drop, the file
  // browser, recent files, scripts).
  // `ofSession`: the dataset a session named, whose state is already the document's.
  void openDataset(const std::string& path, bool ofSession = false);
  Document session() const;  // what the window saves as the last session when it quits
  // Where a physical point (LPS mm) is on the shown image, in window pixels (none: no image yet);
  // scripts click there.
  std::optional<glm::vec2> screenOfPhysical(const glm::dvec3& physicalMm) const;

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr float kPanelWidth = 430;   // the side panel on the right (screen pixels)
  static constexpr float kStatusHeight = 28;  // the status bar at the bottom

  // The frame (gui/app.cpp): the document's one way to change, keys, the viewport window.
  const Document& doc() const { return workstation_.document(); }
  void commit(const Edit& edit);  // to workstation_.apply: every change of the document
  bool popupOpen() const;
  double fitViewZoom() const;  // "fit view": the current view filling the viewport
  template <class PanelEdit>
  void commit(const std::optional<PanelEdit>& edit) {
    if (edit) commit(Edit{*edit});
  }
  void pollJobs();
  void pollHistogram();
  void handleKeys();
  void drawViewportWindow();
  ViewportOverlay viewportOverlay() const;
  glm::dvec2 fitAtZoomOne() const;  // mm the viewport fits at zoom 1 (across, along the axis)
  ViewportFit viewportFit() const;  // the viewport's size (last drawn) and the fit at zoom 1
  // What the window renders of the view: the visible window and each level's isd at the zoom.
  RenderParams zoomedViewParams() const;
  LevelSamplings zoomedLevelSamplings() const;
  // The render-request path (gui/app_render_request.cpp): reads the document, never writes it.
  std::unique_ptr<ProgressiveRenderer> makeRenderer();
  void pollRenderer();
  void requestRender(bool interactive);
  // What the window shows as a render recipe (gui/app_recipe.cpp): exports render it, and the
  // window renders its scene, the recipe without its view, prepared again only when it changes.
  // The panel's (none: no centerlines); regions following the main TF follow `main` (as rendered).
  std::optional<VesselGlyphRecipe> vesselGlyphRecipe(const TransferFunction& main) const;
  std::optional<HybridCprRecipe> hybridRecipe() const;  // the CPR section's; none: off
  std::shared_ptr<const PreparedScene> currentScene();
  std::shared_ptr<const PreparedScene> prepareScene(RenderRecipe recipe, const Centerlines& centerlines);
  RenderRecipe exportRecipe() const;  // of what the last request rendered
  RenderParams viewParams() const;    // the document's view, shading, mode and clipping
  Centerlines exportCenterlines();    // the recipe's centerlines in the volume frame (none: empty)
  // The side panel and status bar (gui/app_panels.cpp): the sections are gui/panel_*.h; these
  // give them what they show and act on what they return.
  void drawSidePanel();
  // A CollapsingHeader whose open state the session keeps.
  bool sectionHeader(const char* title, bool openByDefault = true);
  void noteRect(const std::string& name);  // the last widget's rectangle, for report()
  void noteRect(const std::string& name, ImVec2 min, ImVec2 max);  // a drawn rectangle
  void drawStatusBar();
  void drawTfSection();
  void drawExportSection();
  void pollExport();
  void drawSeriesExport();  // gui/app_series.cpp
  // TF editing: the editor's target (main, focus or context), its undo stack.
  TransferFunction editedTf() const;
  const std::string& editedPreset() const;
  void applyTf(const TransferFunction& tf, const std::string& preset);  // one undo step
  void applyTfChange(const TfChange& change);                           // one undo step
  void adjustByDrag(glm::vec2 px);  // a Shift+drag on the view: TF shift/opacity or MIP window
  void undoTf();
  void redoTf();
  void saveEditedTf();
  void switchTfTarget(TfTarget target);  // gui/app_vessel.cpp
  // Datasets (gui/app_data.cpp).
  void drawDataSection();
  void pollBackgroundJobs();  // data load, centerline load, series export
  bool backgroundBusy() const;
  void replaceDataset(LoadedDataset dataset);
  std::string resetTfForNewDataset();  // what it did, for the status line ("" = nothing)
  // Sessions (gui/app_session.cpp).
  void startSession();  // panel states to apply, recent files, the last session offered
  void applySession(const Document& session);
  void commitSession(const Document& session);
  void drawSessionSection();
  void drawSessionBanner();
  // VesselGlyph (gui/app_vessel.cpp): centerlines loaded in the background, the overlay.
  void drawVesselSection();
  void drawCenterlineOverlay();
  // The crop box's edges and face handles over the image, a handle's drag (gui/app_clip.cpp).
  void drawCropOverlay();
  std::vector<CropHandle> shownCropHandles() const;
  void dragCropFace(glm::dvec2 pointer);
  void drawCropBox(const std::vector<CropHandle>& handles, const std::optional<CropHandle>& hovered);
  void loadVesselCenterlines(const CenterlineLoad& request);  // in the background
  void loadSessionCenterlines();  // the document's centerline file (none: the loaded ones go)
  void pollCenterlineLoad();
  void dropCenterlines();
  void syncVesselCenterlines();  // vessel_'s centerlines from the document's vessel paths
  const Centerlines* framedCenterlines();
  void loadMissingRegionTfs();  // a focus or context TF with no points: its preset
  ImVec2 dvrScreenOf(const ViewGeometry& shownView, const glm::dvec3& pointMm) const;
  // Labels (gui/app_labels.cpp): bone removal, pick and grow, undo, label files.
  void drawLabelsSection();
  void pollLabelJobs();
  void startBoneRemoval();
  void growOnClick();  // right after drawViewport: a click with the grow tool on
  void startLabelRead(const std::string& file);
  void saveLabels(const std::string& file);
  // Stops the renderer meanwhile; `tilesAfter`: the slice tiles of the changed volume, if a job
  // built them ahead (else the renderer refreshes the slices the change touched).
  void changeLabels(const LabelChange& change, bool undo, std::shared_ptr<SliceTiles> tilesAfter = {});
  void stepLabels(bool undo);
  void finishLabelStep(LabelJobResult result, bool cancelled);
  void resetLabels();                   // a new dataset: its own labels, counted anew
  std::string exportLabelFile() const;  // the label file exports name ("" = none or unsaved)
  std::optional<UnsavedLabels> unsavedLabels() const;  // labels an export must write beside it
  // Clicks on the image (gui/app_pick.cpp): the image point of a left click (not a drag) on the
  // viewport, right after drawViewport; the visible point under it (volume frame).
  std::optional<glm::dvec2> clickedImagePoint() const;
  std::optional<PickedPoint> pickVisible(glm::dvec2 imagePoint) const;
  // Vessels (gui/app_vessels.cpp): tracing from clicks, the path list, its undo and files.
  void drawVesselsSection();
  void traceOnClick();                        // right after drawViewport: a click with the Trace tool on
  void traceOnCprClick(const CprPick& pick);  // with the tool on: the centerline point there
  void drawTraceOverlay();
  void requestTrace(const TraceRequest& request);
  void startNextTrace();
  void pollVesselJobs();
  void changeVessels(std::vector<VesselPath> paths, const std::string& what);  // one undo step
  void stepVessels(std::vector<VesselsStep>& from, std::vector<VesselsStep>& to, const char* done);
  void undoVessels();
  void redoVessels();
  void resetTracer();   // new settings or dataset: the next click starts a new tracer
  void resetVessels();  // a new dataset: its paths went with the old one
  void saveVessels(const std::string& file);
  // The file browser (gui/app_browse.cpp), for a purpose, from `current`'s folder.
  void browseFor(BrowserPurpose purpose, const std::string& current);
  void chooseBrowsed(const std::filesystem::path& chosen);
  void drawBrowser();
  void chooseVesselFile(const std::filesystem::path& file);  // what it chose: save or load
  std::optional<Centerlines> unsavedCenterlines() const;     // physical; exports write them beside
  nlohmann::json vesselsReport() const;
  // CPR view (gui/app_cpr.cpp): beside the DVR view, cprViewWidth() wide (0 when hidden).
  void drawCprSection();
  void drawCprView();
  void updateCpr();
  void takeComputedCpr();
  CprLook cprLook() const;
  const Centerlines* cprCenterlines();  // framedCenterlines, null where it throws
  void showCprLook();
  void handleCprMouse(const CprPlacement& placement);
  void moveCprCursorTo(const CprPick& pick);
  std::optional<CenterlinePlace> cprCursorPlace();
  void setCprCursor(CprCursor cursor);
  void stepCprCursor(double mm);
  void drawCprRuler(const CprPlacement& placement);
  void drawCprCursor(const CprPlacement& placement, ImVec2 paneMin, ImVec2 paneMax);
  void drawCrossSectionInset(ImVec2 paneMin, ImVec2 paneMax);
  void markCprOnDvr();
  void moveCprCursorOnClick();  // right after drawViewport: a click near a centerline
  float cprViewWidth() const;
  // The linked slice view (gui/app_slices.cpp): a column beside the image, sliceViewWidth() wide
  // (0 when hidden), left of the CPR view.
  glm::dvec3 sliceCursor() const;  // the document's cursor in the volume, else its centre
  float sliceViewWidth() const;
  void resetSliceView();  // a new dataset: its slices are its own
  void drawSlicesSection();
  void drawSliceView();
  void drawSlicePane(SliceOrientation orientation, ImVec2 min, ImVec2 size,
                     const Centerlines* centerlines);
  void updateSliceTexture(SliceOrientation orientation);
  void drawSliceCrosshair(SliceOrientation orientation);
  void handleSliceMouse(SliceOrientation orientation);
  void moveSliceCursor(glm::dvec3 cursorMm);
  void zoomOrPanSlice(SliceOrientation orientation);
  void moveSliceCursorOnClick();  // right after drawViewport: a click with no tool on
  void drawSliceCursorOnImage();
  nlohmann::json slicesReport() const;
  // The state report's parts (gui/app_report.cpp).
  nlohmann::json dataReport() const;
  nlohmann::json vesselReport() const;
  nlohmann::json cropHandlesReport() const;
  nlohmann::json labelsReport() const;
  nlohmann::json cprReport() const;
  nlohmann::json hybridReport() const;

  LoadedDataset data_;  // before renderer_: the worker reads data_.volume
  Workstation workstation_;
  StreamedTexture texture_;
  std::function<void()> wakeUi_;
  RenderThreads& threads_;                         // the program's: the renderer renders in its arenas
  std::unique_ptr<ProgressiveRenderer> renderer_;  // replaced with the dataset

  // Rendering hand-off.
  std::shared_ptr<const PreparedScene> scene_;  // of the last request (reset with the dataset)
  RenderRecipe sceneRecipe_;                    // what scene_ was prepared from
  Centerlines sceneCenterlines_;                // ... with these centerlines
  std::optional<ProgressiveRequest> lastRequest_;
  std::uint64_t lastRequestId_ = 0;
  std::shared_ptr<const ProgressiveFrame> shown_;  // the frame the texture shows
  ViewGeometry shownView_;  // its view geometry (set with shown_: overlays and picks read it)
  std::shared_ptr<const ProgressiveFrame> incoming_;  // the frame being uploaded
  std::deque<std::pair<std::uint64_t, Clock::time_point>> requestTimes_;
  // Request -> its first image on screen: the start-up request (slice tiles built first) apart.
  double startupImageMs_ = -1, lastFirstImageMs_ = -1, lastUploadMs_ = 0, maxUploadMs_ = 0;
  // The newest renderer's first image: from its replacing the one before (a label change: from
  // before the labels are written; its slice tiles are refreshed in the first frame).
  Clock::time_point rendererSince_ = Clock::now();
  double rendererFirstImageMs_ = -1;
  FrameTimes::Stats firstImage_;
  LatencyTrace latency_;          // input -> image on screen, stage by stage
  Clock::time_point frameStart_;  // this UI frame's: the platform applied its input just before
  FrameTimes frameTimes_;
  double lastFrameMs_ = 0;
  ProgressiveStatus status_;  // this frame's snapshot

  // The panels' own state and what they show.
  TfPanelUi tfPanel_;
  TfTargets tfTargets_;
  std::vector<Preset> presets_;
  std::string message_;  // the last error or notice, shown in the status bar
  std::future<DensityHistogram> histogramJob_;
  std::vector<float> histogram_;  // log counts per density, empty until counted
  std::optional<DensityRange> huRange_;
  bool huCalibrated_ = true;  // core/volume.h looksHuCalibrated, once counted
  ViewportInteraction viewport_;
  WidgetRects widgetRects_;
  bool quit_ = false;

  struct ExportPanel {
    ExportPanelUi ui;
    std::future<std::string> job;
    std::shared_ptr<std::atomic<bool>> cancel;
    Clock::time_point started;
  };
  ExportPanel export_;  // last: its job reads data_ and is waited for first on destruction

  // Data, rotation series, session (after export_: their jobs are cancelled and waited for first).
  FileBrowser browser_;
  BackgroundJob<LoadedDataset> load_;
  std::string loadPath_, loadError_;
  bool loadOfSession_ = false;              // the running load is a session's dataset
  std::optional<Document> pendingSession_;  // applied once that load succeeds
  // The first level's sampling while dragging (render/motion_sampling.h): the budget, the last
  // first-level frame shown, the isd chosen by the last interactive request (kept for the
  // release's request, which then continues above the frame the drag left).
  double motionBudgetMs_ = 40;
  std::optional<MeasuredFrame> lastFirstLevel_;
  std::optional<double> motionIsd_;
  std::string startPreset_;                 // the main TF a new dataset falls back to from an edited one
  std::optional<CropGrab> cropGrab_;        // a crop handle held (until the frame after release)
  bool viewAdjusting_ = false;              // a Shift+drag on the view is under way (one TF undo step)
  std::optional<Document> offeredSession_;  // "Restore last session" banner
  SessionPanelUi sessionPanel_;
  std::map<std::string, bool> panelsToApply_;  // section open states to set on the next frame
  SeriesPanel series_;
  BackgroundJob<SeriesResult> seriesJob_;

  VesselGlyphPanel vessel_;  // the VesselGlyph panel (gui/app_vessel.cpp)
  CprViewPanel cprView_;     // the CPR view (gui/app_cpr.cpp)
  SliceViewPanel slices_;    // the slice view (gui/app_slices.cpp)
  LabelsPanel labels_;       // the Labels section (gui/app_labels.cpp); its job reads data_
  VesselsPanel vessels_;     // the Vessels section (gui/app_vessels.cpp); last: its job reads data_
};

}  // namespace angio
