#include "gui/app.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "core/view_geometry.h"

namespace angio {

namespace {

constexpr std::size_t kRememberedRequests = 256;
// Per UI frame: ~1 ms on a GPU driver, a few ms in software GL; a fast image goes in one frame.
constexpr std::size_t kUploadBytesPerFrame = 3 << 20;

using Ms = std::chrono::duration<double, std::milli>;

// FNV-1a of the shown pixels: lets tests tell images apart without reading screenshots.
std::uint64_t checksum(const std::vector<std::uint8_t>& bytes) {
  std::uint64_t hash = 1469598103934665603ull;
  for (std::uint8_t byte : bytes) hash = (hash ^ byte) * 1099511628211ull;
  return hash;
}

nlohmann::json rectJson(ImVec2 min, ImVec2 max) { return {min.x, min.y, max.x, max.y}; }

nlohmann::json statsJson(const FrameTimes::Stats& stats) {
  return {{"frames", stats.frames}, {"mean_ms", stats.meanMs()}, {"max_ms", stats.maxMs}};
}

}  // namespace

void FrameTimes::Stats::add(double ms) {
  ++frames;
  sumMs += ms;
  maxMs = std::max(maxMs, ms);
}

App::App(LoadedDataset dataset, AppStart start, const GlApi& gl, std::function<void()> wakeUi)
    : data_(std::move(dataset)),
      workstation_(std::move(start.document)),
      texture_(gl),
      wakeUi_(std::move(wakeUi)),
      renderer_(std::make_unique<ProgressiveRenderer>(data_.volume, ProgressiveCallbacks{{}, wakeUi_})),
      presets_(listPresets()),
      cprView_(gl) {
  histogramJob_ = std::async(std::launch::async, [this] { return densityHistogram(data_.volume); });
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is fixed; the session file will hold what persists
  ImGui::StyleColorsDark();
  startSession();
  if (!start.centerlinesFile.empty()) {  // `gui --centerlines` rather than a session's file
    vessel_.ui.path = start.centerlinesFile;
    commit(CenterlineFileEdit{});
    loadVesselCenterlines({vessel_.ui.path, "", CenterlineLoad::From::panel});
  } else {
    loadSessionCenterlines();
  }
}

App::~App() {
  if (export_.cancel) export_.cancel->store(true);
  if (export_.job.valid()) export_.job.wait();
  if (histogramJob_.valid()) histogramJob_.wait();
}

void App::noteRect(const std::string& name) { angio::noteRect(widgetRects_, name); }

void App::commit(const Edit& edit) { workstation_.apply(edit); }


void App::frame(double previousFrameMs) {
  frameStart_ = Clock::now();
  if (previousFrameMs > 0) {
    lastFrameMs_ = previousFrameMs;
    frameTimes_.all.add(previousFrameMs);
    if (status_.rendering == Quality::high) frameTimes_.whileHigh.add(previousFrameMs);
  }
  pollHistogram();
  pollRenderer();
  pollExport();
  pollBackgroundJobs();
  status_ = renderer_->status();

  ImGui::NewFrame();
  handleKeys();
  drawSidePanel();
  drawViewportWindow();
  drawCprView();
  drawStatusBar();
  const ViewState& view = doc().view;
  if (view.autoSpin) commit(RotateEdit{view.spinDegreesPerSecond * ImGui::GetIO().DeltaTime});
  // While anything is held (a drag on the image or the TF plot, a slider, an arrow key) or the
  // view spins, only the fast level is wanted; letting go asks for the full progression.
  const bool interacting = ImGui::IsAnyItemActive() || doc().view.autoSpin ||
                           ImGui::IsKeyDown(ImGui::GetKeyIndex(ImGuiKey_LeftArrow)) ||
                           ImGui::IsKeyDown(ImGui::GetKeyIndex(ImGuiKey_RightArrow));
  ImGui::Render();
  if (doc().vesselGlyph.enabled && vessel_.physical) loadMissingRegionTfs();  // the request's regions need them
  requestRender(interacting);
}

void App::framePresented() { latency_.presented(Clock::now()); }

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
}

// Swaps in the newest finished frame: uploads it in strips (a few per UI frame for a large image)
// and shows it when complete; a frame with the pixels already shown (re-labelled) just replaces it.
void App::pollRenderer() {
  const std::shared_ptr<const ProgressiveFrame> frame = renderer_->latestFrame();
  if (frame && frame != shown_ && frame != incoming_) {
    if (shown_ && frame->serial == shown_->serial && !incoming_) {
      shown_ = frame;
      latency_.shown(*frame, Clock::now());
    } else if (incoming_ && frame->serial == incoming_->serial) {
      incoming_ = frame;
    } else {
      incoming_ = frame;
      latency_.seen(*frame, Clock::now());
      texture_.begin(frame);
    }
  }
  if (!incoming_) return;
  const auto start = Clock::now();
  const bool complete = texture_.step(kUploadBytesPerFrame);
  lastUploadMs_ = Ms(Clock::now() - start).count();
  maxUploadMs_ = std::max(maxUploadMs_, lastUploadMs_);
  if (!complete) return;
  shown_ = std::move(incoming_);
  incoming_.reset();
  latency_.shown(*shown_, Clock::now());
  // Input -> first image of the request that input made (whatever its level).
  const auto asked = std::find_if(requestTimes_.begin(), requestTimes_.end(),
                                  [&](const auto& entry) { return entry.first == shown_->request; });
  if (asked != requestTimes_.end()) {
    lastFirstImageMs_ = Ms(Clock::now() - asked->second).count();
    if (asked->first == 1) startupImageMs_ = lastFirstImageMs_;
    else firstImage_.add(lastFirstImageMs_);
    requestTimes_.erase(requestTimes_.begin(), asked + 1);
  }
}

// Asks for a render when anything that decides the image changed (or an interaction ended).
void App::requestRender(bool interactive) {
  if (!table_ || doc().tf != tableTf_) {
    table_ = std::make_shared<const TfTable>(buildTable(doc().tf));
    tableTf_ = doc().tf;
  }
  ProgressiveRequest request;
  request.params = renderParamsOf(doc());
  request.table = table_;
  request.regions = vesselRegions();
  request.interactive = interactive;
  request.levels = doc().levels;
  if (lastRequest_ && *lastRequest_ == request) return;
  lastRequestId_ = renderer_->request(request);
  latency_.requested(lastRequestId_, frameStart_);
  lastRequest_ = request;
  requestTimes_.emplace_back(lastRequestId_, Clock::now());
  if (requestTimes_.size() > kRememberedRequests) requestTimes_.pop_front();
}

void App::handleKeys() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  const double step = io.KeyShift ? 10 : 1;
  // Arrows turn the patient like a drag in their direction (see drawViewport's grab semantics).
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow))) commit(RotateEdit{step});
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow))) commit(RotateEdit{-step});
  if (io.KeyCtrl && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Z), false)) undoTf();
  if (io.KeyCtrl && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Y), false)) redoTf();
}

void App::drawViewportWindow() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(std::max(io.DisplaySize.x - kPanelWidth - cprViewWidth(), 64.f),
                                  std::max(io.DisplaySize.y - kStatusHeight, 64.f)));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin("##viewport", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::PopStyleVar();

  ViewportImage image;
  ViewportOverlay overlay;
  const glm::dvec3 extent = domainExtent(data_.volume);
  const ViewState& view = doc().view;
  const int a = int(view.axis), b = (a + 1) % 3, c = (a + 2) % 3;
  overlay.fitMm = glm::dvec2(std::max(std::hypot(extent[b], extent[c]), 1e-3), std::max(extent[a], 1e-3));
  char caption[96];
  std::snprintf(caption, sizeof caption, "%.1f deg about %s%s", view.angleDeg, toString(view.axis),
                doc().mode == Compositing::mip ? "   MIP" : "");
  overlay.caption = caption;
  if (shown_ && !texture_.empty()) {
    image = {texture_.id(), shown_->image->width, shown_->image->height,
             shown_->params.sampling.isd * voxelUnit(data_.volume)};
    const Sampling& s = shown_->params.sampling;
    char label[96];
    std::snprintf(label, sizeof label, "%s  %dx%d  isd %.2g osd %.2g %s", toString(shown_->level),
                  image.width, image.height, s.isd, s.osd, toString(s.filter));
    overlay.levelLabel = label;
  }
  viewport_ = drawViewport(image.texture ? &image : nullptr, view, overlay);
  if (viewport_.zoomedOrPanned) commit(ViewEdit{*viewport_.zoomedOrPanned});
  drawCenterlineOverlay();
  moveCprCursorOnClick();
  if (viewport_.rotateDegrees != 0) commit(RotateEdit{viewport_.rotateDegrees});
  ImGui::End();
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
  const bool shownIsNewest = shown_ && !incoming_ && frame == shown_ && shown_->request == lastRequestId_;
  if (shownIsNewest && int(shown_->level) >= int(level)) return true;
  const ProgressiveStatus status = renderer_->status();
  // Finished below `level` (an interactive request): nothing more will come.
  return shownIsNewest && !status.busy && status.request == lastRequestId_;
}

nlohmann::json App::report() const {
  nlohmann::json shown = nullptr;
  if (shown_) {
    const Sampling& s = shown_->params.sampling;
    shown = {{"request", shown_->request},
             {"level", toString(shown_->level)},
             {"width", shown_->image->width},
             {"height", shown_->image->height},
             {"angle_deg", shown_->params.angleDeg},
             {"axis", toString(shown_->params.axis)},
             {"isd", s.isd},
             {"osd", s.osd},
             {"filter", toString(s.filter)},
             {"render_ms", shown_->renderMs},
             {"samples", shown_->samples},
             {"checksum", std::to_string(checksum(shown_->rgb8))}};
  }
  const ProgressiveStatus status = renderer_->status();
  nlohmann::json levels = nlohmann::json::object();
  for (int q = 0; q < kQualityLevels; ++q) {
    const LevelTiming& t = status.levels[q];
    if (t.done) levels[toString(Quality(q))] = {{"ms", t.ms}, {"samples_per_second", t.samplesPerSecond()}};
  }
  const OrientationLetters letters = orientationLetters(doc().view.axis, doc().view.angleDeg);
  nlohmann::json layout = {{"viewport", rectJson(viewport_.min, viewport_.max)},
                           {"tf_plot", rectJson(tfView_.plotMin, tfView_.plotMax)}};
  for (const auto& [name, rect] : widgetRects_) layout[name] = rectJson(rect.first, rect.second);
  return {
      {"state", nlohmann::json::parse(toJson(doc()))},
      {"runtime",
       {{"dataset", {{"name", data_.name},
                     {"dims", {data_.volume.dims.x, data_.volume.dims.y, data_.volume.dims.z}}}},
        {"shown", shown},
        {"newest_request", lastRequestId_},
        {"busy", status.busy},
        {"levels", levels},
        {"last_interrupt_ms", status.lastInterruptMs},
        {"startup_to_first_image_ms", startupImageMs_},
        {"input_to_first_image_ms", {{"last", lastFirstImageMs_}, {"count", firstImage_.frames},
                                     {"mean", firstImage_.meanMs()}, {"max", firstImage_.maxMs}}},
        {"latency", latency_.report()},
        {"texture_upload_ms", {{"last", lastUploadMs_}, {"max", maxUploadMs_}}},
        {"ui_frame_ms", {{"all", statsJson(frameTimes_.all)}, {"while_high", statsJson(frameTimes_.whileHigh)}}},
        {"orientation", {{"right", std::string(1, letters.right)}, {"left", std::string(1, letters.left)},
                         {"top", std::string(1, letters.top)}, {"bottom", std::string(1, letters.bottom)}}},
        {"tf_undo_available", tfHistory_.canUndo()},
        {"message", message_},
        {"data", dataReport()},
        {"vessel_glyph", vesselReport()},
        {"layout", layout}}},
  };
}

}  // namespace angio
