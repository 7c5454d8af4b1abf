#include "cli/progress_line.h"

#include <cstdio>

#include <unistd.h>

namespace angio {

ProgressLine::ProgressLine(std::string label) : label_(std::move(label)) {}

ProgressLine::~ProgressLine() {
  if (printed_)
    std::fprintf(stderr, "%s%s done in %.1f s\n", ::isatty(STDERR_FILENO) ? "\r" : "", label_.c_str(),
                 std::chrono::duration<double>(Clock::now() - start_).count());
}

void ProgressLine::operator()(double fraction) {
  // A log file gets the closing line only; rewriting a line in place is for terminals.
  static const bool terminal = ::isatty(STDERR_FILENO);
  std::lock_guard lock(mutex_);
  if (!terminal) {
    printed_ = printed_ || Clock::now() - start_ >= std::chrono::seconds(1);
    return;
  }
  const auto now = Clock::now();
  if (now - start_ < std::chrono::seconds(1)) return;
  if (printed_ && now - lastPrint_ < std::chrono::milliseconds(250)) return;
  std::fprintf(stderr, "\r%s %3d%%", label_.c_str(), int(fraction * 100));
  std::fflush(stderr);
  lastPrint_ = now;
  printed_ = true;
}

}  // namespace angio
