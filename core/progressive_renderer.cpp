#include "core/progressive_renderer.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <exception>

#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>

#include "core/fast_raycaster.h"

namespace angio {

namespace {

constexpr int kBackgroundNice = 10;

// Lowers the calling thread's priority (Linux: nice is per thread). Raising it back would need
// privileges, so threads stay lowered; in the GUI process every oneTBB thread is background work.
void lowerThisThreadsPriority() {
  setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), kBackgroundNice);
}

using Ms = std::chrono::duration<double, std::milli>;

bool sameSampling(const Sampling& a, const Sampling& b) {
  return a.isd == b.isd && a.osd == b.osd && a.filter == b.filter && a.ert == b.ert;
}

// Everything but the sampling, which each level replaces.
bool sameView(const RenderParams& a, const RenderParams& b) {
  return a.axis == b.axis && a.angleDeg == b.angleDeg && a.shading.enabled == b.shading.enabled &&
         a.shading.ka == b.shading.ka && a.shading.kd == b.shading.kd &&
         a.compositing == b.compositing && a.mip.window == b.mip.window &&
         a.mip.level == b.mip.level;
}

// The same TFs and regions (objects, not contents: a change makes new ones).
bool sameClassification(const ProgressiveRequest& a, const ProgressiveRequest& b) {
  return a.table == b.table && a.regions == b.regions;
}

bool sameLevels(const LevelSamplings& a, const LevelSamplings& b) {
  for (int q = 0; q < kQualityLevels; ++q)
    if (!sameSampling(a[q], b[q])) return false;
  return true;
}

// The oneTBB arena all progressive renders run in: every thread entering it is lowered.
struct BackgroundArena {
  struct Observer : tbb::task_scheduler_observer {
    explicit Observer(tbb::task_arena& arena) : tbb::task_scheduler_observer(arena) { observe(true); }
    void on_scheduler_entry(bool) override { lowerThisThreadsPriority(); }
  };
  tbb::task_arena arena;
  Observer observer{arena};
};

// One for the process, never destroyed: oneTBB threads keep references to the observer until
// they exit, which is at process exit.
tbb::task_arena& backgroundArena() {
  static BackgroundArena* const instance = new BackgroundArena;
  return instance->arena;
}

int lastLevel(const ProgressiveRequest& request) {
  return request.interactive ? int(Quality::fast) : int(Quality::high);
}

}  // namespace

std::vector<Rgb8Image> halvedLevels(const std::vector<std::uint8_t>& rgb8, int width, int height) {
  std::vector<Rgb8Image> levels;
  if (width <= 0 || height <= 0) return levels;
  const std::vector<std::uint8_t>* source = &rgb8;
  int w = width, h = height;
  while (w > 1 || h > 1) {
    Rgb8Image half;
    half.width = std::max(w / 2, 1);
    half.height = std::max(h / 2, 1);
    half.rgb.resize(std::size_t(half.width) * half.height * 3);
    for (int y = 0; y < half.height; ++y) {
      const int y0 = std::min(2 * y, h - 1), y1 = std::min(2 * y + 1, h - 1);
      for (int x = 0; x < half.width; ++x) {
        const int x0 = std::min(2 * x, w - 1), x1 = std::min(2 * x + 1, w - 1);
        for (int c = 0; c < 3; ++c) {
          const auto at = [&](int xx, int yy) { return int((*source)[(std::size_t(yy) * w + xx) * 3 + c]); };
          const int sum = at(x0, y0) + at(x1, y0) + at(x0, y1) + at(x1, y1);
          half.rgb[(std::size_t(y) * half.width + x) * 3 + c] = std::uint8_t((sum + 2) / 4);
        }
      }
    }
    levels.push_back(std::move(half));
    source = &levels.back().rgb;
    w = levels.back().width;
    h = levels.back().height;
  }
  return levels;
}

LevelSamplings defaultLevelSamplings() {
  return {qualitySampling(Quality::fast), qualitySampling(Quality::medium),
          qualitySampling(Quality::high)};
}

double ProgressiveStatus::estimatedProgress() const {
  if (!rendering || rows <= 0) return 0;
  return std::min(double(rowsDone) / rows, 1.0);
}

ProgressiveRenderer::ProgressiveRenderer(const Volume& volume,
                                         ProgressiveCallbacks callbacks)
    : volume_(volume),
      callbacks_(std::move(callbacks)),
      worker_([this] { workerLoop(); }) {}

ProgressiveRenderer::~ProgressiveRenderer() {
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
         sameView(r.params, request.params) && sameLevels(r.levels, request.levels);
}

std::uint64_t ProgressiveRenderer::request(ProgressiveRequest request) {
  std::uint64_t id = 0;
  {
    std::lock_guard lock(mutex_);
    if (isInProgress(request)) return status_.request;
    id = ++nextId_;
    if (status_.rendering && !runningLevelStaysUseful(request)) {
      cancelRequestedAt_ = Clock::now();
      cancel_.store(true);
    }
    pending_ = Job{id, std::move(request)};
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
         sameSampling(running.levels[level], request.levels[level]);
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
  published_.wait_for(lock, timeout, [&] {
    return reached() || status_.request != id || !status_.busy;
  });
  return reached();
}

void ProgressiveRenderer::workerLoop() {
  lowerThisThreadsPriority();
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return quit_ || pending_; });
      if (quit_) return;
      job = std::move(*pending_);
      pending_.reset();
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

// Slice tiles per axis (rebuilt when it changes, not cancellable: ~0.5 s at 512x512x1200) and
// tile visibility per TF table, or per region TFs (a tile is visible if any region's TF shows it).
void ProgressiveRenderer::prepare(const Job& job) {
  const Axis axis = job.request.params.axis;
  if (!tiles_ || tiles_->axis != axis) {
    tiles_.reset();  // free the old tiles before building the new ones
    tiles_ = buildSliceTiles(volume_, axis);
    classifiedTable_.reset();
    classifiedRegions_.reset();
  }
  const std::shared_ptr<const RegionSource>& regions = job.request.regions;
  if (classifiedTable_ != job.request.table || classifiedRegions_ != regions) {
    visibleTiles_ = regions ? classifyTiles(*tiles_, RegionTables{&regionScratch_, regions->focus.get(),
                                                                  regions->context.get(),
                                                                  regions->outside.get()})
                            : classifyTiles(*tiles_, *job.request.table);
    classifiedTable_ = job.request.table;
    classifiedRegions_ = regions;
  }
}

// A level whose image the newest frame already shows for the same view and TF is not rendered
// again (e.g. the release after a drag continues at medium); that frame is re-labelled as this
// request's so the UI and waitForLevel see the level reached.
int ProgressiveRenderer::firstLevelToRender(const Job& job) {
  std::lock_guard lock(mutex_);
  if (!latest_ || latest_->request >= job.id) return 0;
  const ProgressiveRequest& r = job.request;
  const int shown = int(latest_->level);
  const bool same = sameView(latest_->params, r.params) &&
                    sameSampling(latest_->params.sampling, r.levels[shown]) &&
                    latest_->table == r.table && latest_->regions == r.regions;
  if (!same) return 0;
  auto relabelled = std::make_shared<ProgressiveFrame>(*latest_);
  relabelled->request = job.id;
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

void ProgressiveRenderer::publish(const Job& job, Quality level, Image image, double ms,
                                  std::uint64_t samples) {
  auto frame = std::make_shared<ProgressiveFrame>();
  frame->request = job.id;
  frame->level = level;
  frame->params = job.request.params;
  frame->params.sampling = job.request.levels[int(level)];
  frame->table = job.request.table;
  frame->regions = job.request.regions;
  frame->rgb8 = toRgb8(image);
  frame->mipmaps = halvedLevels(frame->rgb8, image.width, image.height);
  frame->image = images_->share(std::move(image));
  frame->renderMs = ms;
  frame->samples = samples;
  {
    std::lock_guard lock(mutex_);
    frame->serial = ++nextSerial_;
  }
  if (callbacks_.beforePublish) callbacks_.beforePublish(*frame);
  {
    std::lock_guard lock(mutex_);
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

// One level: plain DVR with the request's table, or VesselGlyph with the regions of this level's
// view (built here, so their time counts in the level's) and the source's finish step.
Image ProgressiveRenderer::renderLevel(const Job& job, const RenderParams& params,
                                       FastRenderStats& stats) {
  FastRenderOptions options;
  options.cancel = &cancel_;
  options.rowsDone = &rowsDone_;
  {
    std::lock_guard lock(mutex_);
    status_.rows = makeViewGeometry(volume_, params).height;
  }
  rowsDone_ = 0;
  Image recycled = images_->take();
  options.recycle = &recycled;
  const RegionSource* regions = job.request.regions.get();
  if (!regions) return renderFast(volume_, *tiles_, visibleTiles_, *job.request.table, params, options, &stats);
  const ViewGeometry view = makeViewGeometry(volume_, params);
  regions->build(view, regionScratch_);
  const RegionTables tables{&regionScratch_, regions->focus.get(), regions->context.get(),
                            regions->outside.get()};
  Image image = renderFast(volume_, *tiles_, visibleTiles_, tables, params, options, &stats);
  if (regions->finish && !stats.cancelled) regions->finish(view, regionScratch_, image);
  return image;
}

void ProgressiveRenderer::runJob(const Job& job) {
  backgroundArena().execute([&] { prepare(job); });
  for (int q = firstLevelToRender(job); q <= lastLevel(job.request); ++q) {
    const Quality level = Quality(q);
    if (!beginLevel(level)) return;
    RenderParams params = job.request.params;
    params.sampling = job.request.levels[q];
    FastRenderStats stats;
    const auto start = Clock::now();
    Image image;
    backgroundArena().execute([&] { image = renderLevel(job, params, stats); });
    const double ms = Ms(Clock::now() - start).count();
    if (stats.cancelled) {
      images_->giveBack(std::move(image));
      std::lock_guard lock(mutex_);
      status_.lastInterruptMs = Ms(Clock::now() - cancelRequestedAt_).count();
      status_.rendering.reset();
      return;
    }
    publish(job, level, std::move(image), ms, stats.samples);
  }
}

}  // namespace angio
