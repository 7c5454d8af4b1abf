#include "render/progressive_renderer.h"

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

// Below the process's own priority (nice steps; relative, so under `nice -n -10` the gaps stay).
constexpr int kFastNiceSteps = 5;
constexpr int kBackgroundNiceSteps = 10;

id_t thisThread() { return id_t(syscall(SYS_gettid)); }

// Thread priorities (Linux: nice is per thread), measured with bench/input_latency.sh.
// The fast level is what a user moving the mouse waits for. Below the UI thread, so that the UI's
// own drawing (software GL rasterises on threads of the UI's priority) finishes first when both
// want the cores - at the UI's priority both took 2-3x longer and input -> screen doubled - but
// only a little: at an absolute nice 10 (20 steps below a `nice -n -10` UI) it waited behind the
// UI and everything else on a loaded machine, 0.1-1 s from input to screen.
// The levels above fast are background work, lower still - but only where a thread can be raised
// back (RLIMIT_NICE or CAP_SYS_NICE): oneTBB threads move between the two arenas, and a thread left
// lowered would render the next fast level at background priority. Without that right both
// levels render at the fast level's priority; a high render still yields to input, which cancels
// it within a row.
struct ThreadPriorities {
  int fast = 0, background = 0;

  static ThreadPriorities probe() {
    const int process = getpriority(PRIO_PROCESS, thisThread());
    ThreadPriorities p;
    p.fast = p.background = std::min(process + kFastNiceSteps, 19);
    const int lowered = std::min(process + kBackgroundNiceSteps, 19);
    bool restorable = false;
    std::thread([&] {  // a throw-away thread: lowering it is harmless if raising fails
      restorable = setpriority(PRIO_PROCESS, thisThread(), lowered) == 0 &&
                   setpriority(PRIO_PROCESS, thisThread(), p.fast) == 0;
    }).join();
    if (restorable) p.background = lowered;
    return p;
  }
};

const ThreadPriorities& priorities() {
  static const ThreadPriorities instance = ThreadPriorities::probe();
  return instance;
}

using Ms = std::chrono::duration<double, std::milli>;

// Everything but the sampling, which each level replaces.
bool sameView(RenderParams a, const RenderParams& b) {
  a.sampling = b.sampling;
  return a == b;
}

// The same TFs and regions (objects, not contents: a change makes new ones).
bool sameClassification(const ProgressiveRequest& a, const ProgressiveRequest& b) {
  return a.table == b.table && a.regions == b.regions;
}

// A oneTBB arena whose threads (oneTBB's and the progressive worker) run at `nice` while in it.
struct PriorityArena {
  struct Observer : tbb::task_scheduler_observer {
    Observer(tbb::task_arena& arena, int nice) : tbb::task_scheduler_observer(arena), nice(nice) { observe(true); }
    void on_scheduler_entry(bool) override {
      if (getpriority(PRIO_PROCESS, thisThread()) != nice) setpriority(PRIO_PROCESS, thisThread(), nice);
    }
    int nice;
  };
  explicit PriorityArena(int nice) : observer(arena, nice) {}
  tbb::task_arena arena;
  Observer observer;
};

// Where a level renders: fast just below the UI, the others in the background. One pair
// for the process, never destroyed: oneTBB threads keep references to the observers until they
// exit, which is at process exit.
tbb::task_arena& arenaFor(Quality level) {
  static PriorityArena* const foreground = new PriorityArena(priorities().fast);
  static PriorityArena* const background = new PriorityArena(priorities().background);
  return (level == Quality::fast ? foreground : background)->arena;
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
         sameView(r.params, request.params) && r.levels == request.levels;
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
  published_.wait_for(lock, timeout, [&] {
    return reached() || status_.request != id || !status_.busy;
  });
  return reached();
}

void ProgressiveRenderer::workerLoop() {
  priorities();  // probed before the first request, not on its time
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
                    latest_->params.sampling == r.levels[shown] &&
                    latest_->table == r.table && latest_->regions == r.regions;
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
  frame->table = job.request.table;
  frame->regions = job.request.regions;
  frame->rgb8 = toRgb8(image);
  frame->mipmaps = halvedLevels(frame->rgb8, image.width, image.height);
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
  arenaFor(Quality::fast).execute([&] { prepare(job); });
  for (int q = firstLevelToRender(job); q <= lastLevel(job.request); ++q) {
    const Quality level = Quality(q);
    if (!beginLevel(level)) return;
    RenderParams params = job.request.params;
    params.sampling = job.request.levels[q];
    FastRenderStats stats;
    RequestTimeline timeline = job.timeline;
    timeline.renderStart = Clock::now();
    Image image;
    arenaFor(level).execute([&] { image = renderLevel(job, params, stats); });
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
