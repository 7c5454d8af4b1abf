#pragma once
// A progress line on stderr for work that may take more than a second: silent for the first
// second, then "label 42%" rewritten in place at most 4 times a second (on a terminal; otherwise
// only the closing "label done in N s"). Callable from any thread.
#include <chrono>
#include <mutex>
#include <string>

namespace angio {

class ProgressLine {
 public:
  explicit ProgressLine(std::string label);
  ~ProgressLine();  // ends the line if anything was printed
  void operator()(double fraction);

 private:
  using Clock = std::chrono::steady_clock;
  std::string label_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point lastPrint_{};
  bool printed_ = false;
  std::mutex mutex_;
};

}  // namespace angio
