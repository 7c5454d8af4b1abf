#include "gui/app.h"
#include "gui/study_banner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include <imgui.h>

#include "core/view_geometry.h"

namespace angio {

void FrameTimes::Stats::add(double ms) {
  ++frames;
  sumMs += ms;
  maxMs = std::max(maxMs, ms);
}

App::App(LoadedDataset dataset, AppStart start, const GlApi& gl, RenderThreads& threads,
         std::function<void()> wakeUi)
    : data_(std::move(dataset)), workstation_(std::move(start.document)), texture_(gl),
      wakeUi_(std::move(wakeUi)), threads_(threads), renderer_(makeRenderer()), presets_(listPresets()),
      cprView_(gl), slices_(gl) {
  histogramJob_ = std::async(std::launch::async, [this] { return densityHistogram(data_.volume); });
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is fixed; the session file will hold what persists
  ImGui::StyleColorsDark();
  motionBudgetMs_ = start.motionBudgetMs;
  startPreset_ = doc().tfPreset.empty() && !presets_.empty() ? presets_.front().id : doc().tfPreset;
  syncVesselCenterlines();
  startSession();
  if (!isPhantomName(doc().dataset)) {  // a dataset given on the command line is a recent file too
    std::vector<std::string> recent = doc().recentFiles;
    addRecentFile(recent, absoluteDataset(doc().dataset));
    commit(RecentFilesEdit{recent});
  }
  labels_.pendingFile = start.labelsFile.empty() ? doc().labels.file : start.labelsFile;
  resetLabels();
  if (!start.centerlinesFile.empty()) {  // `gui --centerlines` rather than a session's file
    vessel_.ui.path = start.centerlinesFile;
    commit(CenterlineFileEdit{});
    loadVesselCenterlines({vessel_.ui.path, "", CenterlineLoad::From::panel});
  } else {
    loadSessionCenterlines();
  }
}

// The renderer of the shown dataset: each frame's display image made on its worker, the UI woken
// when one is published, with the slice tiles made ahead (by the load, or kept over a label change).
std::unique_ptr<ProgressiveRenderer> App::makeRenderer() {
  ProgressiveCallbacks callbacks;
  callbacks.makeDisplay = makeDisplayImage;
  callbacks.afterPublish = wakeUi_;
  return std::make_unique<ProgressiveRenderer>(data_.volume, threads_, std::move(callbacks),
                                               std::exchange(data_.tiles, {}));
}

App::~App() {
  if (export_.cancel) export_.cancel->store(true);
  if (export_.job.valid()) export_.job.wait();
  if (histogramJob_.valid()) histogramJob_.wait();
}

void App::noteRect(const std::string& name) { angio::noteRect(widgetRects_, name); }
void App::noteRect(const std::string& name, ImVec2 min, ImVec2 max) { widgetRects_[name] = {min, max}; }

void App::commit(const Edit& edit) {
  workstation_.apply(edit);
  syncVesselCenterlines();
}

// Poll the jobs, draw (the panels' edits applied as they return them), ask for a render.
void App::frame(double previousFrameMs) {
  frameStart_ = Clock::now();
  if (previousFrameMs > 0) {
    lastFrameMs_ = previousFrameMs;
    frameTimes_.all.add(previousFrameMs);
    if (status_.rendering == Quality::high) frameTimes_.whileHigh.add(previousFrameMs);
  }
  pollJobs();
  ImGui::NewFrame();
  handleKeys();
  drawSidePanel();
  drawViewportWindow();
  drawSliceView();
  drawCprView();
  drawStatusBar();
  const ViewState& view = doc().view;
  if (view.autoSpin) commit(RotateEdit{view.spinDegreesPerSecond * ImGui::GetIO().DeltaTime});
  // While anything is held (a drag on the image or the TF plot, a slider, an arrow key) or the
  // view spins, only the fast level is wanted; letting go asks for the full progression.
  const bool arrowHeld = !popupOpen() && (ImGui::IsKeyDown(ImGui::GetKeyIndex(ImGuiKey_LeftArrow)) ||
                                          ImGui::IsKeyDown(ImGui::GetKeyIndex(ImGuiKey_RightArrow)));
  // (A press in a slice or the CPR pane is not an interaction with the 3-D view.)
  const bool interacting =
      (ImGui::IsAnyItemActive() && !slices_.held && !cprView_.held) || doc().view.autoSpin || arrowHeld;
  ImGui::Render();
  if (doc().vesselGlyph.enabled && vessel_.physical)
    loadMissingRegionTfs();  // the request's regions need them
  requestRender(interacting);
}

void App::framePresented() { latency_.presented(Clock::now()); }

void App::pollJobs() {
  pollHistogram();
  pollRenderer();
  pollExport();
  pollBackgroundJobs();
  pollLabelJobs();
  pollVesselJobs();
  status_ = renderer_->status();
}

void App::pollHistogram() {
  if (!histogramJob_.valid() ||
      histogramJob_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return;
  const DensityHistogram counts = histogramJob_.get();
  histogram_ = logHistogram(counts);
  DensityRange range{kDensityLevels - 1, 0};
  for (int d = 0; d < kDensityLevels; ++d)
    if (counts[d]) range.minDensity = std::min(range.minDensity, d), range.maxDensity = d;
  huRange_ = range;
  huCalibrated_ = looksHuCalibrated(counts);
}

// A modal (the file browser) or an open combo has the keys: the view does not turn behind it.
bool App::popupOpen() const {
  return ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
}

double App::fitViewZoom() const {
  const ImVec2 size(viewport_.max.x - viewport_.min.x, viewport_.max.y - viewport_.min.y);
  if (size.x <= 0 || size.y <= 0) return 1;
  const ViewState& view = doc().view;
  return zoomToFitView(domainExtent(data_.volume), view.axis, view.angleDeg, glm::dvec2(size.x, size.y));
}

void App::handleKeys() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput || popupOpen()) return;
  const double step = io.KeyShift ? 10 : 1;
  // Arrows turn the patient like a drag in their direction (see drawViewport's grab semantics).
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow))) commit(RotateEdit{step});
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow))) commit(RotateEdit{-step});
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_DownArrow))) stepCprCursor(step);
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_UpArrow))) stepCprCursor(-step);
  // Ctrl+Z undoes the Vessels section's last change while it has the focus, else the TF's.
  const bool z = io.KeyCtrl && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Z), false);
  if (z && vessels_.focused) io.KeyShift ? redoVessels() : undoVessels();
  else if (z) undoTf();
  if (io.KeyCtrl && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Y), false)) redoTf();
}

void App::drawViewportWindow() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(
      ImVec2(std::max(io.DisplaySize.x - kPanelWidth - cprViewWidth() - sliceViewWidth(), 64.f),
             std::max(io.DisplaySize.y - kStatusHeight, 64.f)));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin("##viewport", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::PopStyleVar();

  ViewportImage image;
  if (shown_ && !texture_.empty()) {
    const ViewGeometry& geometry = shownView_;
    const glm::dvec3 offset = geometry.centre - geometry.extent * 0.5;
    image = {texture_.id(),
             shown_->image->width,
             shown_->image->height,
             geometry.pixelMm,
             {glm::dot(offset, geometry.right), glm::dot(offset, geometry.up)}};
  }
  viewport_ = drawViewport(image.texture ? &image : nullptr, doc().view, viewportOverlay());
  if (viewport_.zoomedOrPanned) commit(ViewEdit{*viewport_.zoomedOrPanned});
  drawCenterlineOverlay();
  drawCropOverlay();
  moveCprCursorOnClick();
  growOnClick();
  traceOnClick();
  moveSliceCursorOnClick();
  drawTraceOverlay();
  drawSliceCursorOnImage();
  if (viewport_.rotateDegrees != 0) commit(RotateEdit{viewport_.rotateDegrees});
  if (viewport_.adjustPx != glm::vec2(0.f)) adjustByDrag(viewport_.adjustPx);
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) viewAdjusting_ = false;  // the gesture ended
  ImGui::End();
}

// The fit of the volume at zoom 1, the angle caption, the shown level's label.
ViewportOverlay App::viewportOverlay() const {
  ViewportOverlay overlay;
  const ViewState& view = doc().view;
  overlay.fitMm = fitAtZoomOne();
  char caption[96];
  std::snprintf(caption, sizeof caption, "%.1f deg about %s%s", view.angleDeg, toString(view.axis),
                doc().mode == Compositing::mip ? "   MIP" : "");
  overlay.caption = caption;
  overlay.banner = studyBanner(data_.study);
  if (!shown_ || texture_.empty()) return overlay;
  const Sampling& s = shown_->params.sampling;
  char along[48];  // how the rays are integrated: samples every osd, or adaptively
  if (s.adaptive && doc().mode == Compositing::dvr)
    std::snprintf(along, sizeof along, "adaptive %.2g from %.2g", s.adaptive->tolerance,
                  s.adaptive->initialStep);
  else if (s.adaptiveSampling && doc().mode == Compositing::dvr)
    std::snprintf(along, sizeof along, "osd %.2g 3-D adaptive L%d/%d", s.osd, s.adaptiveSampling->levels,
                  s.adaptiveSampling->rayLevels);
  else std::snprintf(along, sizeof along, "osd %.2g", s.osd);
  char label[128];
  std::snprintf(label, sizeof label, "%s  %dx%d  isd %.2g %s %s%s", toString(shown_->level),
                shown_->image->width, shown_->image->height, s.isd, along, toString(s.filter),
                s.preintegrated ? " pre-integrated" : "");
  overlay.levelLabel = label;
  return overlay;
}

// The volume's extent across the rotation axis (its diagonal, so any angle fits) and along it.
glm::dvec2 App::fitAtZoomOne() const {
  const glm::dvec3 extent = domainExtent(data_.volume);
  const int a = int(doc().view.axis), b = (a + 1) % 3, c = (a + 2) % 3;
  return {std::max(std::hypot(extent[b], extent[c]), 1e-3), std::max(extent[a], 1e-3)};
}

ViewportFit App::viewportFit() const {
  return {glm::dvec2(viewport_.max.x - viewport_.min.x, viewport_.max.y - viewport_.min.y),
          fitAtZoomOne()};
}

RenderParams App::zoomedViewParams() const {
  RenderParams params = viewParams();
  params.window = visibleWindow(doc().view, viewportFit());
  return params;
}

LevelSamplings App::zoomedLevelSamplings() const {
  const double perMm = viewportPixelsPerMm(viewportFit(), doc().view.zoom);
  const double screenIsd = perMm > 0 ? 1 / (perMm * voxelUnit(data_.volume)) : 0;
  return zoomedLevels(doc().levels, doc().view.zoom, screenIsd);
}

FramePacing App::pacing() const {
  if (doc().view.autoSpin || incoming_ || renderer_->latestFrame() != shown_ ||
      ImGui::IsAnyMouseDown() || ImGui::IsAnyItemActive())
    return FramePacing::continuous;
  if (renderer_->status().busy || histogramJob_.valid() || export_.job.valid() || backgroundBusy())
    return FramePacing::progress;
  return FramePacing::idle;
}

bool App::settled(Quality level) const {
  const std::shared_ptr<const ProgressiveFrame> frame = renderer_->latestFrame();
  if (export_.job.valid() || backgroundBusy()) return false;
  const bool shownIsNewest =
      shown_ && !incoming_ && frame == shown_ && shown_->request == lastRequestId_;
  if (shownIsNewest && int(shown_->level) >= int(level)) return true;
  const ProgressiveStatus status = renderer_->status();
  // Finished below `level` (an interactive request): nothing more will come.
  return shownIsNewest && !status.busy && status.request == lastRequestId_;
}

}  // namespace angio
