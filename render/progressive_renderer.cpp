#include "render/progressive_renderer.h"

#include <algorithm>
#include <exception>

#include "core/fast_raycaster.h"

namespace angio {

namespace {

using Ms = std::chrono::duration<double, std::milli>;

// Everything but the sampling, which each level replaces.
bool sameView(RenderParams a, const RenderParams& b) {
  a.sampling = b.sampling;
  return a == b;
}

// The same TFs and regions (objects, not contents: a change makes a new scene).
bool sameClassification(const ProgressiveRequest& a, const ProgressiveRequest& b) {
  return a.scene == b.scene;
}

int lastLevel(const ProgressiveRequest& request) {
  return request.interactive ? int(Quality::fast) : int(Quality::high);
}

}  // namespace

LevelSamplings defaultLevelSamplings() {
  return {qualitySampling(Quality::fast), qualitySampling(Quality::medium),
          qualitySampling(Quality::high)};
}

double ProgressiveStatus::estimatedProgress() const {
  if (!rendering || rows <= 0) return 0;
  return std::min(double(rowsDone) / rows, 1.0);
}

ProgressiveRenderer::ProgressiveRenderer(const Volume& volume, RenderThreads& threads,
                                         ProgressiveCallbacks callbacks, TilesAhead tiles)
    : volume_(volume), threads_(threads), callbacks_(std::move(callbacks)),
      frames_(volume, std::move(tiles)), worker_([this] { workerLoop(); }) {}

ProgressiveRenderer::~ProgressiveRenderer() { stopWorker(); }

TilesAhead ProgressiveRenderer::stopAndReleaseTiles() {
  stopWorker();
  return frames_.releaseTiles();
}

void ProgressiveRenderer::stopWorker() {
  if (!worker_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
    cancel_.store(true);
  }
  wake_.notify_all();
  worker_.join();
}

bool ProgressiveRenderer::isInProgress(const ProgressiveRequest& request) const {
  const std::optional<Job>& newest = pending_ ? pending_ : current_;
  if (!newest || !status_.busy) return false;
  const ProgressiveRequest& r = newest->request;
  return sameClassification(r, request) && r.interactive == request.interactive &&
         sameView(r.params, request.params) && r.levels == request.levels;
}

std::uint64_t ProgressiveRenderer::request(ProgressiveRequest request) {
  std::uint64_t id = 0;
  {
    std::lock_guard lock(mutex_);
    if (isInProgress(request)) return status_.request;
    id = ++nextId_;
    const bool otherAxis = status_.preparing && *status_.preparing != request.params.axis;
    if ((status_.rendering && !runningLevelStaysUseful(request)) || otherAxis) {
      cancelRequestedAt_ = Clock::now();
      cancel_.store(true);
    }
    pending_ = Job{id, std::move(request), {}};
    pending_->timeline.requested = Clock::now();
    status_.request = id;
    status_.busy = true;
    status_.levels = {};
  }
  wake_.notify_one();
  return id;
}

// The running level is let finish when the new request would render the same image at that level
// (e.g. a drag's release), or when both are fast and the new one is interactive: cancelling a fast
// render for every mouse move would show nothing while the mouse moves faster than fast renders.
bool ProgressiveRenderer::runningLevelStaysUseful(const ProgressiveRequest& request) const {
  if (!current_ || !status_.rendering) return false;
  const int level = int(*status_.rendering);
  const ProgressiveRequest& running = current_->request;
  if (request.interactive && level == int(Quality::fast)) return true;
  return sameClassification(running, request) && sameView(running.params, request.params) &&
         running.levels[level] == request.levels[level];
}

std::shared_ptr<const ProgressiveFrame> ProgressiveRenderer::latestFrame() const {
  std::lock_guard lock(mutex_);
  return latest_;
}

ProgressiveStatus ProgressiveRenderer::status() const {
  std::lock_guard lock(mutex_);
  ProgressiveStatus status = status_;
  if (status.rendering) {
    status.renderingMs = Ms(Clock::now() - levelStart_).count();
    status.rowsDone = rowsDone_.load(std::memory_order_relaxed);
  }
  return status;
}

bool ProgressiveRenderer::waitForLevel(std::uint64_t id, Quality level,
                                       std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  const auto reached = [&] {
    return latest_ && latest_->request == id && int(latest_->level) >= int(level);
  };
  published_.wait_for(lock, timeout,
                      [&] { return reached() || status_.request != id || !status_.busy; });
  return reached();
}

void ProgressiveRenderer::workerLoop() {
  for (;;) {
    Job job;
    const Clock::time_point free = Clock::now();
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return quit_ || pending_; });
      if (quit_) return;
      job = std::move(*pending_);
      pending_.reset();
      job.timeline.workerFree = free;
      job.timeline.pickedUp = Clock::now();
      current_ = job;
      // Cleared under the lock that request() sets it under: a cancel meant for the previous
      // job cannot leak into this one, and one meant for this job cannot be lost.
      cancel_.store(false);
    }
    try {
      runJob(job);
    } catch (const std::exception& error) {
      std::lock_guard lock(mutex_);
      status_.error = error.what();
      status_.rendering.reset();
    }
    {
      std::lock_guard lock(mutex_);
      current_.reset();
      if (!pending_) status_.busy = false;
    }
    published_.notify_all();
    if (callbacks_.afterPublish) callbacks_.afterPublish();
  }
}

// Slice tiles per axis (built when it changes, unless kept from before or built ahead by a load;
// a request about another axis interrupts the build) and tile visibility per scene. False: cancelled.
bool ProgressiveRenderer::prepare(const Job& job) {
  {
    std::lock_guard lock(mutex_);
    status_.preparing = job.request.params.axis;
    status_.tilesBuilt = 0;
  }
  const auto tilesBuilt = [this](double fraction) {
    std::lock_guard lock(mutex_);
    status_.tilesBuilt = fraction;
  };
  bool prepared = false;
  threads_.arenaFor(Quality::fast).execute([&] {
    prepared = frames_.prepare(job.request.scene, job.request.params.axis,
                               job.request.params.compositing, &cancel_, tilesBuilt);
  });
  std::lock_guard lock(mutex_);
  status_.preparing.reset();
  if (!prepared) {
    status_.lastInterruptMs = Ms(Clock::now() - cancelRequestedAt_).count();
    if (pending_) pending_->timeline.cancelSeen = Clock::now();
  }
  return prepared;
}

// A level whose image the newest frame already shows for the same view and TF is not rendered
// again (e.g. the release after a drag continues at medium); that frame is re-labelled as this
// request's so the UI and waitForLevel see the level reached.
int ProgressiveRenderer::firstLevelToRender(const Job& job) {
  std::lock_guard lock(mutex_);
  if (!latest_ || latest_->request >= job.id) return 0;
  const ProgressiveRequest& r = job.request;
  const int shown = int(latest_->level);
  const bool same = sameView(latest_->params, r.params) && latest_->params.sampling == r.levels[shown] &&
                    latest_->scene == r.scene;
  if (!same) return 0;
  auto relabelled = std::make_shared<ProgressiveFrame>(*latest_);
  relabelled->request = job.id;
  relabelled->timeline = job.timeline;  // not rendered for this request: no render times
  latest_ = relabelled;
  if (status_.request == job.id)
    status_.levels[shown] = {true, relabelled->renderMs, relabelled->samples};
  return shown + 1;
}

// Marks `level` as running unless a newer request is waiting (then false: drop this job).
bool ProgressiveRenderer::beginLevel(Quality level) {
  std::lock_guard lock(mutex_);
  if (pending_ || quit_) return false;
  status_.rendering = level;
  status_.expectedMs = lastLevelMs_[int(level)];
  levelStart_ = Clock::now();
  return true;
}

void ProgressiveRenderer::publish(const Job& job, Quality level, Image image,
                                  const RequestTimeline& timeline, std::uint64_t samples) {
  const double ms = Ms(timeline.renderEnd - timeline.renderStart).count();
  auto frame = std::make_shared<ProgressiveFrame>();
  frame->request = job.id;
  frame->level = level;
  frame->params = job.request.params;
  frame->params.sampling = job.request.levels[int(level)];
  frame->scene = job.request.scene;
  if (callbacks_.makeDisplay) frame->display = callbacks_.makeDisplay(image);
  frame->image = images_->share(std::move(image));
  frame->renderMs = ms;
  frame->samples = samples;
  frame->timeline = timeline;
  {
    std::lock_guard lock(mutex_);
    frame->serial = ++nextSerial_;
  }
  if (callbacks_.beforePublish) callbacks_.beforePublish(*frame);
  {
    std::lock_guard lock(mutex_);
    frame->timeline.published = Clock::now();
    latest_ = frame;
    lastLevelMs_[int(level)] = ms;
    status_.rendering.reset();
    if (status_.request == job.id) status_.levels[int(level)] = {true, ms, samples};
    // The job's last frame: idle from now on (not only once runJob has returned), so a UI that
    // shows this frame never sees "busy" with nothing left to come.
    if (int(level) == lastLevel(job.request) && !pending_) status_.busy = false;
  }
  published_.notify_all();
  if (callbacks_.afterPublish) callbacks_.afterPublish();
}

// One level through the frame renderer: plain DVR, or VesselGlyph with the regions of this
// level's view (built there, so their time counts in the level's) and the scene's finish step.
Image ProgressiveRenderer::renderLevel(const Job& job, const RenderParams& params,
                                       FastRenderStats& stats) {
  {
    std::lock_guard lock(mutex_);
    status_.rows = makeViewGeometry(volume_, params).height;
  }
  rowsDone_ = 0;
  Image recycled = images_->take();
  return frames_.render(job.request.scene, params, {&cancel_, &rowsDone_, &recycled, {}}, &stats);
}

void ProgressiveRenderer::runJob(const Job& job) {
  if (!prepare(job)) return;
  for (int q = firstLevelToRender(job); q <= lastLevel(job.request); ++q) {
    const Quality level = Quality(q);
    if (!beginLevel(level)) return;
    RenderParams params = job.request.params;
    params.sampling = job.request.levels[q];
    FastRenderStats stats;
    RequestTimeline timeline = job.timeline;
    timeline.renderStart = Clock::now();
    Image image;
    threads_.arenaFor(level).execute([&] { image = renderLevel(job, params, stats); });
    timeline.renderEnd = Clock::now();
    if (stats.cancelled) {
      images_->giveBack(std::move(image));
      std::lock_guard lock(mutex_);
      status_.lastInterruptMs = Ms(timeline.renderEnd - cancelRequestedAt_).count();
      status_.rendering.reset();
      if (pending_) pending_->timeline.cancelSeen = timeline.renderEnd;
      return;
    }
    publish(job, level, std::move(image), timeline, stats.samples);
  }
}

}  // namespace angio
