#pragma once
// Input -> image on screen, step by step (the "latency" block of the state report / --state-out):
// where the time between an input that changes the view and the first image showing it goes.
// The renderer stamps each frame's hand-off (core/progressive_renderer.h, RequestTimeline); the UI
// adds when it saw the frame, finished the texture upload and presented it. Cheap enough to be
// always on: a few clock reads per request, a bounded buffer of samples per stage.
//
// Stages of the first frame shown of each request (ms; they add up to "total"):
//   input_to_request  UI frame start (input applied) -> request() returned: ImGui frame, TF table
//   request_to_pickup request() -> the worker took it; split into
//     worker_busy       .. the worker finishing (or cancelling) the render it was running
//     wake              .. the worker waking up and taking the job
//   pickup_to_render  slice tiles / tile classification before the level starts
//   render            the level's renderFast (VesselGlyph regions and finish step included)
//   publish           8-bit conversion and mipmaps
//   publish_to_ui     published -> the UI thread saw the frame (its next poll)
//   upload            seen -> texture upload complete (one or more UI frames)
//   present           upload complete -> the UI frame showing it was presented (swap / glFinish)
//   total             input -> presented
// Besides: "cancel" (request() -> the render it interrupted returned, for requests that
// interrupted one) and "input_to_screen" over every input-made request, also those superseded
// before they got an image of their own (then: until the first image of a newer request).
#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/progressive_renderer.h"

namespace angio {

// The last kKept values of one quantity (ms), with count, mean, median, 95th percentile, min, max.
class LatencySamples {
 public:
  static constexpr std::size_t kKept = 4096;
  void add(double ms);
  int count() const { return count_; }
  nlohmann::json json() const;  // {count, mean, median, p95, min, max}; median, p95 of the kept values

 private:
  std::vector<double> kept_;
  std::size_t next_ = 0;
  int count_ = 0;
  double sum_ = 0, min_ = 0, max_ = 0;
};

class LatencyTrace {
 public:
  using Clock = std::chrono::steady_clock;

  // Input applied at `inputAt` made request `id` (ids of a renderer's requests grow; the start-up
  // request, 1, is not an input and is left out, and so is a repeated id).
  void requested(std::uint64_t id, Clock::time_point inputAt);
  // The UI took `frame` from latestFrame() and started its upload / completed it; a frame whose
  // pixels were already shown (re-labelled) is shown without an upload.
  void seen(const ProgressiveFrame& frame, Clock::time_point at);
  void shown(const ProgressiveFrame& frame, Clock::time_point at);
  // The platform presented the UI frame (buffer swap, or glFinish headless).
  void presented(Clock::time_point at);
  void restart();  // a new renderer: request ids start over

  nlohmann::json report() const;

 private:
  struct Input {
    std::uint64_t id;
    Clock::time_point at;
  };
  struct OnScreen {  // shown, waiting for the present
    std::uint64_t request = 0;
    Quality level = Quality::fast;
    RequestTimeline timeline;
    Clock::time_point seen, shown;
  };

  std::deque<Input> inputs_;     // requests not on screen yet, oldest first
  std::uint64_t lastInput_ = 0;  // newest request in inputs_ so far
  std::uint64_t seenSerial_ = 0;
  Clock::time_point seenAt_{};
  std::optional<OnScreen> onScreen_;
  std::uint64_t lastTraced_ = 0;  // newest request whose first frame went into the stages
  int superseded_ = 0;            // input-made requests that never got an image of their own
  std::array<int, kQualityLevels> firstLevels_{};  // level of each traced request's first frame

  enum Stage {
    inputToRequest,
    requestToPickup,
    workerBusy,
    wake,
    pickupToRender,
    render,
    publish,
    publishToUi,
    upload,
    present,
    total,
    cancel,
    inputToScreen,
    stageCount
  };
  std::array<LatencySamples, stageCount> stages_;
};

}  // namespace angio
