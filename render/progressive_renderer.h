#pragma once
// Progressive rendering (thesis sec. 4.4, "Interactive Mode"): every request is rendered at the
// fast, then the medium, then the high quality level by one background thread, and each finished
// level is handed to the UI. A newer request interrupts the running render through the fast
// raycaster's cancel flag (checked within each image row, so the render returns within one row's
// time) and the worker starts over at fast. Interactive requests (dragging, spinning) render only
// fast. A request is a prepared scene (render/prepared_scene.h: the recipe's TFs, regions and
// hybrid) seen with one view; each level renders it through a FrameRenderer
// (render/frame_renderer.h), the path every other caller renders through.
//
// Priorities: the levels render in the arenas of the RenderThreads the program made
// (render/render_threads.h): fast just below the UI, the others in the background.
//
// Hand-off: the UI thread polls latestFrame() (a shared pointer swapped under a mutex) and never
// waits for the worker. waitForLevel() is for tests and scripts only.
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/fast_raycaster.h"
#include "core/image.h"
#include "core/render_params.h"
#include "core/volume.h"
#include "render/frame_renderer.h"
#include "render/image_pool.h"
#include "render/prepared_scene.h"
#include "render/render_threads.h"

namespace angio {

constexpr int kQualityLevels = 3;  // fast, medium, high, in rendering order

using LevelSamplings = std::array<Sampling, kQualityLevels>;
LevelSamplings defaultLevelSamplings();  // the rendering model's table

struct ProgressiveRequest {
  // What to render. A different scene object = a TF, region or hybrid change (scenes are
  // immutable: a change makes a new one).
  std::shared_ptr<const PreparedScene> scene;
  RenderParams params;       // the view; sampling is replaced by each level's
  bool interactive = false;  // dragging or spinning: fast only
  LevelSamplings levels = defaultLevelSamplings();

  // The scene compares as an object, the rest by value.
  friend bool operator==(const ProgressiveRequest&, const ProgressiveRequest&) = default;
};

// The form in which the UI shows a frame (8-bit pixels, mipmaps: gui/display_image.h), made by
// ProgressiveCallbacks::makeDisplay on the worker so the UI thread only uploads it. render/ only
// carries it.
struct DisplayImage;

// When a frame's request passed each step of the hand-off (steady clock; a default time point:
// did not happen). Cheap (a few clock reads per level): always recorded, for the latency
// breakdown the UI reports (gui/latency_trace.h).
struct RequestTimeline {
  using TimePoint = std::chrono::steady_clock::time_point;
  TimePoint requested;   // request() returned the id
  TimePoint workerFree;  // the worker was ready for it: done with (or cancelled) what it ran
  TimePoint pickedUp;    // the worker took it
  TimePoint cancelSeen;  // the render this request interrupted returned (none interrupted: unset)
  TimePoint renderStart, renderEnd;  // this frame's level, in renderFast (with regions, finish)
  TimePoint published;               // 8-bit image and mipmaps made, latestFrame() returns the frame
};

// One finished level of one request.
struct ProgressiveFrame {
  std::uint64_t request = 0;  // the id request() returned
  std::uint64_t serial = 0;   // grows with every published frame
  Quality level = Quality::fast;
  RenderParams params;                          // as rendered, with the level's sampling
  std::shared_ptr<const PreparedScene> scene;   // the request's
  std::shared_ptr<const Image> image;           // linear RGBA
  std::shared_ptr<const DisplayImage> display;  // ProgressiveCallbacks::makeDisplay's (null: none)
  double renderMs = 0;
  std::uint64_t samples = 0;
  RequestTimeline timeline;  // a re-labelled frame's: its request's up to pickedUp, no render
};

struct LevelTiming {
  bool done = false;
  double ms = 0;
  std::uint64_t samples = 0;
  double samplesPerSecond() const { return ms > 0 ? double(samples) / (ms * 1e-3) : 0; }
};

struct ProgressiveStatus {
  std::uint64_t request = 0;         // the newest request's id
  bool busy = false;                 // the worker has something to do for it
  std::optional<Quality> rendering;  // the level being rendered right now
  std::optional<Axis> preparing;     // slice tiles about this axis being built or classified
  double tilesBuilt = 0;             // while preparing: the fraction of those tiles built so far
  double renderingMs = 0;            // how long that level has been running
  double expectedMs = 0;             // that level's last duration (0 = not known yet)
  int rowsDone = 0, rows = 0;        // image rows of the running level finished / in all
  std::array<LevelTiming, kQualityLevels> levels;  // of the newest request
  double lastInterruptMs = -1;                     // request() -> interrupted render returned, last time
  std::string error;  // a render that threw (e.g. out of memory), else empty

  // Progress of the running level: its finished rows (rows render in parallel, in any order).
  double estimatedProgress() const;
};

// Optional hooks, called on the worker thread; they must be quick.
struct ProgressiveCallbacks {
  // Makes the frame's display form from its image, just before it is published.
  std::function<std::shared_ptr<const DisplayImage>(const Image&)> makeDisplay;
  // With each frame just before it is published (so a waiter never sees a frame this has not).
  std::function<void(const ProgressiveFrame&)> beforePublish;
  // After each frame is published and when the worker goes idle: e.g. wake the UI thread.
  std::function<void()> afterPublish;
};

class ProgressiveRenderer {
 public:
  // `volume` and `threads` must outlive the renderer; every request's scene is of `volume`.
  // `tiles`: the volume's slice tiles built ahead (FrameRenderer), so that the first frame need
  // not build them (0.3-0.4 s at 512x512x1200; a request about another axis interrupts it).
  ProgressiveRenderer(const Volume& volume, RenderThreads& threads, ProgressiveCallbacks callbacks = {},
                      TilesAhead tiles = {});
  ~ProgressiveRenderer();  // interrupts and joins the worker

  // Interrupts and joins the worker for good (no request after it) and gives up the slice tiles
  // it built, e.g. for the next renderer after a label change to refresh the slices it touched.
  TilesAhead stopAndReleaseTiles();
  ProgressiveRenderer(const ProgressiveRenderer&) = delete;
  ProgressiveRenderer& operator=(const ProgressiveRenderer&) = delete;

  // Starts rendering `request` and returns its id. Interrupts the running render, except that an
  // interactive request lets a running fast render finish (otherwise a drag faster than the fast
  // level would never show a frame), and a build of slice tiles unless the request is about
  // another axis (it goes on with the next request about its axis); the worker then takes only
  // the newest pending request.
  // A request identical to the one in progress returns that one's id and changes nothing; one
  // identical to the newest finished frame's view and TF continues above that frame's level.
  std::uint64_t request(ProgressiveRequest request);

  // The newest request's best finished frame, or the previous request's until the new one has
  // one; null before the first frame.
  std::shared_ptr<const ProgressiveFrame> latestFrame() const;
  ProgressiveStatus status() const;

  // Blocks until request `id` has a frame at `level` or better (true), or it can no longer get
  // one: superseded, finished lower (interactive), or timed out (false). Not for the UI thread.
  bool waitForLevel(std::uint64_t id, Quality level, std::chrono::milliseconds timeout) const;

 private:
  using Clock = std::chrono::steady_clock;
  struct Job {
    std::uint64_t id = 0;
    ProgressiveRequest request;
    RequestTimeline timeline;  // up to pickedUp
  };

  void stopWorker();
  void workerLoop();
  void runJob(const Job& job);
  bool prepare(const Job& job);
  int firstLevelToRender(const Job& job);
  bool beginLevel(Quality level);
  void publish(const Job& job, Quality level, Image image, const RequestTimeline& timeline,
               std::uint64_t samples);
  bool isInProgress(const ProgressiveRequest& request) const;
  bool runningLevelStaysUseful(const ProgressiveRequest& request) const;
  Image renderLevel(const Job& job, const RenderParams& params, FastRenderStats& stats);

  const Volume& volume_;
  RenderThreads& threads_;
  ProgressiveCallbacks callbacks_;

  mutable std::mutex mutex_;
  std::condition_variable wake_;               // worker: a request or quit
  mutable std::condition_variable published_;  // waiters: a frame, or the worker went idle
  std::optional<Job> pending_;
  std::optional<Job> current_;  // the job the worker is running
  std::uint64_t nextId_ = 0;
  std::uint64_t nextSerial_ = 0;
  bool quit_ = false;
  Clock::time_point levelStart_{};
  Clock::time_point cancelRequestedAt_{};
  std::array<double, kQualityLevels> lastLevelMs_{};
  std::shared_ptr<const ProgressiveFrame> latest_;
  ProgressiveStatus status_;
  std::atomic<bool> cancel_{false};

  FrameRenderer frames_;  // worker-only: tiles, classification, region buffers
  std::shared_ptr<ImagePool> images_ = std::make_shared<ImagePool>();
  std::atomic<int> rowsDone_{0};  // of the level being rendered

  std::thread worker_;  // last: starts after everything above is constructed
};

}  // namespace angio
