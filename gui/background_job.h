#pragma once
// A piece of UI work off the UI thread (loading a dataset, exporting a rotation series): a
// future for the result, a cancel flag and a progress fraction the work updates. The UI polls
// ready() each frame and never waits; destroying the job cancels it and waits for it.
#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <utility>

namespace angio {

struct JobControl {
  std::atomic<bool> cancel{false};
  std::atomic<double> progress{0.0};  // [0, 1]
};

template <class Result>
class BackgroundJob {
 public:
  BackgroundJob() = default;
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;
  ~BackgroundJob() { stop(); }

  // Runs work(JobControl&) -> Result on its own thread. The caller makes sure the work's inputs
  // outlive the job (or are captured by value).
  template <class Work>
  void start(Work work) {
    stop();
    control_ = std::make_shared<JobControl>();
    started_ = std::chrono::steady_clock::now();
    result_ = std::async(std::launch::async,
                         [control = control_, work = std::move(work)] { return work(*control); });
  }

  bool running() const { return result_.valid(); }
  bool ready() const {
    return result_.valid() && result_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
  }
  // The result (or the work's exception, rethrown) once ready(); the job is then not running.
  Result take() { return result_.get(); }
  void cancel() {
    if (control_) control_->cancel.store(true);
  }
  bool cancelRequested() const { return control_ && control_->cancel.load(); }
  double progress() const { return control_ ? control_->progress.load() : 0.0; }
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  }
  // Cancels and waits; the result (or error) is dropped.
  void stop() {
    cancel();
    if (result_.valid()) result_.wait();
    result_ = {};
  }

 private:
  std::shared_ptr<JobControl> control_;
  std::future<Result> result_;
  std::chrono::steady_clock::time_point started_{};
};

}  // namespace angio
