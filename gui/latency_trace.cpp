#include "gui/latency_trace.h"

#include <algorithm>

namespace angio {

namespace {

using Ms = std::chrono::duration<double, std::milli>;
using TimePoint = LatencyTrace::Clock::time_point;

double msBetween(TimePoint from, TimePoint to) { return Ms(to - from).count(); }

constexpr const char* kStageNames[] = {"input_to_request",
                                       "request_to_pickup",
                                       "worker_busy",
                                       "wake",
                                       "pickup_to_render",
                                       "render",
                                       "publish",
                                       "publish_to_ui",
                                       "upload",
                                       "present",
                                       "total",
                                       "cancel",
                                       "input_to_screen"};

}  // namespace

void LatencySamples::add(double ms) {
  if (kept_.size() < kKept) kept_.push_back(ms);
  else kept_[next_] = ms;
  next_ = (next_ + 1) % kKept;
  min_ = count_ ? std::min(min_, ms) : ms;
  max_ = count_ ? std::max(max_, ms) : ms;
  sum_ += ms;
  ++count_;
}

nlohmann::json LatencySamples::json() const {
  if (!count_) return {{"count", 0}};
  std::vector<double> sorted = kept_;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  const double median = n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
  // Nearest rank: the smallest kept value with at least 95 % of them at or below it.
  const double p95 = sorted[(95 * n + 99) / 100 - 1];
  return {{"count", count_}, {"mean", sum_ / count_}, {"median", median},
          {"p95", p95},      {"min", min_},           {"max", max_}};
}

void LatencyTrace::requested(std::uint64_t id, Clock::time_point inputAt) {
  if (id <= std::max<std::uint64_t>(lastInput_, 1)) return;
  lastInput_ = id;
  inputs_.push_back({id, inputAt});
  if (inputs_.size() > LatencySamples::kKept) inputs_.pop_front();
}

void LatencyTrace::seen(const ProgressiveFrame& frame, Clock::time_point at) {
  seenSerial_ = frame.serial;
  seenAt_ = at;
}

void LatencyTrace::shown(const ProgressiveFrame& frame, Clock::time_point at) {
  const bool uploaded = frame.serial == seenSerial_;
  onScreen_ = OnScreen{frame.request, frame.level, frame.timeline, uploaded ? seenAt_ : at, at};
}

void LatencyTrace::presented(Clock::time_point at) {
  if (!onScreen_) return;
  const OnScreen shown = *onScreen_;
  onScreen_.reset();
  // Every input up to this request now has its image on screen (an older one: a newer image).
  std::optional<TimePoint> inputAt;
  while (!inputs_.empty() && inputs_.front().id <= shown.request) {
    stages_[inputToScreen].add(msBetween(inputs_.front().at, at));
    if (inputs_.front().id == shown.request) inputAt = inputs_.front().at;
    else ++superseded_;
    inputs_.pop_front();
  }
  // The stages of the request's first frame, when it was rendered for it (not re-labelled).
  const RequestTimeline& t = shown.timeline;
  if (!inputAt || shown.request <= lastTraced_ || t.renderStart == TimePoint{}) return;
  lastTraced_ = shown.request;
  ++firstLevels_[int(shown.level)];
  const TimePoint ready = std::max(t.workerFree, t.requested);  // the worker could take it
  stages_[inputToRequest].add(msBetween(*inputAt, t.requested));
  stages_[requestToPickup].add(msBetween(t.requested, t.pickedUp));
  stages_[workerBusy].add(msBetween(t.requested, ready));
  stages_[wake].add(msBetween(ready, t.pickedUp));
  stages_[pickupToRender].add(msBetween(t.pickedUp, t.renderStart));
  stages_[render].add(msBetween(t.renderStart, t.renderEnd));
  stages_[publish].add(msBetween(t.renderEnd, t.published));
  stages_[publishToUi].add(msBetween(t.published, shown.seen));
  stages_[upload].add(msBetween(shown.seen, shown.shown));
  stages_[present].add(msBetween(shown.shown, at));
  stages_[total].add(msBetween(*inputAt, at));
  if (t.cancelSeen != TimePoint{}) stages_[cancel].add(msBetween(t.requested, t.cancelSeen));
}

void LatencyTrace::restart() {
  inputs_.clear();
  lastInput_ = 0;
  onScreen_.reset();
  seenSerial_ = 0;
  lastTraced_ = 0;
}

nlohmann::json LatencyTrace::report() const {
  nlohmann::json stages = nlohmann::json::array();
  for (int s = 0; s < stageCount; ++s) {
    nlohmann::json row = stages_[s].json();
    row["stage"] = kStageNames[s];
    stages.push_back(row);
  }
  nlohmann::json levels = nlohmann::json::object();
  for (int q = 0; q < kQualityLevels; ++q) levels[toString(Quality(q))] = firstLevels_[q];
  return {{"stages_ms", stages}, {"superseded_requests", superseded_}, {"first_frame_levels", levels}};
}

}  // namespace angio
