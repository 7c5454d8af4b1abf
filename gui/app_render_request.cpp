// The render-request path of App: what the window shows goes to the progressive renderer as a
// request (the prepared scene of the window's recipe, gui/app_recipe.cpp, and the document's
// view), and finished frames come back as the viewport's texture. It reads the document, never
// writes it.
#include <algorithm>
#include <chrono>
#include <memory>
#include <string>

#include "gui/app.h"

namespace angio {

namespace {

constexpr std::size_t kRememberedRequests = 256;
// Per UI frame: ~1 ms on a GPU driver, a few ms in software GL; a fast image goes in one frame.
constexpr std::size_t kUploadBytesPerFrame = 3 << 20;

using Ms = std::chrono::duration<double, std::milli>;

}  // namespace

// Swaps in the newest finished frame: uploads it in strips (a few per UI frame for a large image)
// and shows it when complete; a frame with the pixels already shown (re-labelled) just replaces it.
void App::pollRenderer() {
  const std::shared_ptr<const ProgressiveFrame> frame = renderer_->latestFrame();
  if (frame && frame != shown_ && frame != incoming_) {
    if (shown_ && frame->serial == shown_->serial && !incoming_) {
      shown_ = frame;
      shownView_ = makeViewGeometry(data_.volume, shown_->params);
      latency_.shown(*frame, Clock::now());
    } else if (incoming_ && frame->serial == incoming_->serial) {
      incoming_ = frame;
    } else {
      incoming_ = frame;
      latency_.seen(*frame, Clock::now());
      texture_.begin(frame->display);
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
  shownView_ = makeViewGeometry(data_.volume, shown_->params);
  if (shown_->level == Quality::fast && shown_->renderMs > 0)
    lastFirstLevel_ = MeasuredFrame{shown_->renderMs, shown_->params.sampling.isd};
  latency_.shown(*shown_, Clock::now());
  // Input -> first image of the request that input made (whatever its level).
  const auto asked = std::find_if(requestTimes_.begin(), requestTimes_.end(),
                                  [&](const auto& entry) { return entry.first == shown_->request; });
  if (asked != requestTimes_.end()) {
    lastFirstImageMs_ = Ms(Clock::now() - asked->second).count();
    if (asked->first == 1) {
      if (startupImageMs_ < 0) startupImageMs_ = lastFirstImageMs_;
      rendererFirstImageMs_ = Ms(Clock::now() - rendererSince_).count();
    } else {
      firstImage_.add(lastFirstImageMs_);
    }
    requestTimes_.erase(requestTimes_.begin(), asked + 1);
  }
}

// Asks for a render when anything that decides the image changed (or an interaction ended).
void App::requestRender(bool interactive) {
  ProgressiveRequest request;
  request.scene = currentScene();
  request.params = zoomedViewParams();
  request.interactive = interactive;
  request.levels = zoomedLevelSamplings();
  if (interactive) motionIsd_ = motionSampling(request.levels, lastFirstLevel_, motionBudgetMs_).isd;
  if (motionIsd_) request.levels[int(Quality::fast)].isd = *motionIsd_;
  if (lastRequest_ && *lastRequest_ == request) return;
  // A value typed into a field (Ctrl+click on a slider takes any text) that no renderer can
  // finish is not sent: the image shown stays, the problem is said.
  std::string problem = renderParamsProblem(request.params);
  for (const Sampling& level : request.levels)
    if (problem.empty()) problem = samplingProblem(level);
  if (!problem.empty()) {
    message_ = "not rendered: " + problem;
    return;
  }
  lastRequestId_ = renderer_->request(request);
  latency_.requested(lastRequestId_, frameStart_);
  lastRequest_ = request;
  requestTimes_.emplace_back(lastRequestId_, Clock::now());
  if (requestTimes_.size() > kRememberedRequests) requestTimes_.pop_front();
}

}  // namespace angio
