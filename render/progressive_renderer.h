#pragma once
// Progressive rendering (thesis sec. 4.4, "Interactive Mode"): every request is rendered at the
// fast, then the medium, then the high quality level by one background thread, and each finished
// level is handed to the UI. A newer request interrupts the running render through renderFast's
// cancel flag (checked before each image row, so the render returns within one row's time) and
// the worker starts over at fast. Interactive requests (dragging, spinning) render only fast.
//
// Priorities: the fast level is what a hand on the mouse waits for; its threads run 5 nice steps
// below the process (the UI's own drawing, the last step to the screen, goes first, but the render
// is not starved by other work on the machine). The levels above it are background work: 10 steps
// below, where the OS lets a thread be raised back for the next fast level, else at fast's
// priority (progressive_renderer.cpp). The UI thread gets a core when it needs one.
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
#include "render/image_pool.h"
#include "core/region_intervals.h"
#include "core/render_params.h"
#include "core/slice_tiles.h"
#include "core/transfer_function.h"
#include "core/view_geometry.h"
#include "core/volume.h"

namespace angio {

constexpr int kQualityLevels = 3;  // fast, medium, high, in rendering order

using LevelSamplings = std::array<Sampling, kQualityLevels>;
LevelSamplings defaultLevelSamplings();  // the rendering model's table

// VesselGlyph for a request (thesis ch. 5): the ray regions of each level's view (the view
// depends on the level's isd) and a TF per region. core knows no centerlines: `build` is whatever
// makes the regions (vessel/vessel_glyph.h's RayRegionBuilder in the app). It is called on the
// worker thread only, one call at a time per renderer, with the same `out` every time so its
// buffers are reused; a source shared with other threads must guard its builder itself.
struct RegionSource {
  std::function<void(const ViewGeometry& view, RayRegions& out)> build;
  std::shared_ptr<const TfTable> focus;    // null: the focus is not rendered
  std::shared_ptr<const TfTable> context;  // null: no context
  std::shared_ptr<const TfTable> outside;  // null: the outside is clipped
  // Optional: called on the worker after each level's render (not after a cancelled one), with
  // that level's view and regions, before the frame is made from the image; may change the image
  // in place (the app's DVR+CPR hybrid composites the projected CPR into the focus footprint).
  // Its time counts in the level's.
  std::function<void(const ViewGeometry& view, const RayRegions& regions, Image& image)> finish;
};

struct ProgressiveRequest {
  RenderParams params;                   // sampling is replaced by each level's
  std::shared_ptr<const TfTable> table;  // a different table object = a TF change
  // Set: VesselGlyph rendering, `table` unused. A different source object = a change (sources
  // are immutable: a change of the regions' shape or of a region's TF makes a new one).
  std::shared_ptr<const RegionSource> regions;
  bool interactive = false;              // dragging or spinning: fast only
  LevelSamplings levels = defaultLevelSamplings();

  // TFs and regions compare as objects (a change makes new ones), the rest by value.
  friend bool operator==(const ProgressiveRequest&, const ProgressiveRequest&) = default;
};

// 8-bit RGB pixels, rows top to bottom, no padding.
struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

// The image halved again and again (2x2 box filter, sizes floor(n / 2), at least 1) down to 1x1,
// starting with the first half: the mipmap levels above level 0 of a texture.
std::vector<Rgb8Image> halvedLevels(const std::vector<std::uint8_t>& rgb8, int width, int height);

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
  TimePoint published;   // 8-bit image and mipmaps made, latestFrame() returns the frame
};

// One finished level of one request.
struct ProgressiveFrame {
  std::uint64_t request = 0;  // the id request() returned
  std::uint64_t serial = 0;   // grows with every published frame
  Quality level = Quality::fast;
  RenderParams params;                 // as rendered, with the level's sampling
  std::shared_ptr<const TfTable> table;
  std::shared_ptr<const RegionSource> regions;  // the request's (null: plain DVR)
  std::shared_ptr<const Image> image;  // linear RGBA
  std::vector<std::uint8_t> rgb8;      // toRgb8(*image), ready for a texture upload
  std::vector<Rgb8Image> mipmaps;      // halvedLevels(rgb8): made here, off the UI thread
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
  std::uint64_t request = 0;          // the newest request's id
  bool busy = false;                  // the worker has something to do for it
  std::optional<Quality> rendering;   // the level being rendered right now
  double renderingMs = 0;             // how long that level has been running
  double expectedMs = 0;              // that level's last duration (0 = not known yet)
  int rowsDone = 0, rows = 0;         // image rows of the running level finished / in all
  std::array<LevelTiming, kQualityLevels> levels;  // of the newest request
  double lastInterruptMs = -1;        // request() -> interrupted render returned, last time
  std::string error;                  // a render that threw (e.g. out of memory), else empty

  // Progress of the running level: its finished rows (rows render in parallel, in any order).
  double estimatedProgress() const;
};

// Optional hooks, called on the worker thread; they must be quick.
struct ProgressiveCallbacks {
  // With each frame just before it is published (so a waiter never sees a frame this has not).
  std::function<void(const ProgressiveFrame&)> beforePublish;
  // After each frame is published and when the worker goes idle: e.g. wake the UI thread.
  std::function<void()> afterPublish;
};

class ProgressiveRenderer {
 public:
  // `volume` must outlive the renderer.
  explicit ProgressiveRenderer(const Volume& volume, ProgressiveCallbacks callbacks = {});
  ~ProgressiveRenderer();  // interrupts and joins the worker
  ProgressiveRenderer(const ProgressiveRenderer&) = delete;
  ProgressiveRenderer& operator=(const ProgressiveRenderer&) = delete;

  // Starts rendering `request` and returns its id. Interrupts the running render, except that an
  // interactive request lets a running fast render finish (otherwise a drag faster than the fast
  // level would never show a frame); the worker then takes only the newest pending request.
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

  void workerLoop();
  void runJob(const Job& job);
  void prepare(const Job& job);
  int firstLevelToRender(const Job& job);
  bool beginLevel(Quality level);
  void publish(const Job& job, Quality level, Image image, const RequestTimeline& timeline,
               std::uint64_t samples);
  bool isInProgress(const ProgressiveRequest& request) const;
  bool runningLevelStaysUseful(const ProgressiveRequest& request) const;
  Image renderLevel(const Job& job, const RenderParams& params, FastRenderStats& stats);

  const Volume& volume_;
  ProgressiveCallbacks callbacks_;

  mutable std::mutex mutex_;
  std::condition_variable wake_;                // worker: a request or quit
  mutable std::condition_variable published_;   // waiters: a frame, or the worker went idle
  std::optional<Job> pending_;
  std::optional<Job> current_;                  // the job the worker is running
  std::uint64_t nextId_ = 0;
  std::uint64_t nextSerial_ = 0;
  bool quit_ = false;
  Clock::time_point levelStart_{};
  Clock::time_point cancelRequestedAt_{};
  std::array<double, kQualityLevels> lastLevelMs_{};
  std::shared_ptr<const ProgressiveFrame> latest_;
  ProgressiveStatus status_;
  std::atomic<bool> cancel_{false};

  // Worker-only state: the empty-space structure for the current axis and TF.
  std::optional<SliceTiles> tiles_;
  std::shared_ptr<const TfTable> classifiedTable_;
  std::shared_ptr<const RegionSource> classifiedRegions_;
  std::vector<std::uint8_t> visibleTiles_;
  RayRegions regionScratch_;  // the regions of the level being rendered (buffers reused)
  std::shared_ptr<ImagePool> images_ = std::make_shared<ImagePool>();
  std::atomic<int> rowsDone_{0};  // of the level being rendered

  std::thread worker_;  // last: starts after everything above is constructed
};

}  // namespace angio
