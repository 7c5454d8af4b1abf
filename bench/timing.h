#pragma once
// Small timing helpers shared by the benchmarks: wall-clock milliseconds and medians.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

namespace angio {

using BenchClock = std::chrono::steady_clock;

inline double msSince(BenchClock::time_point start) {
  return std::chrono::duration<double, std::milli>(BenchClock::now() - start).count();
}

// CPU time of the whole process (all threads) in ms: unlike wall time it hardly changes when other
// processes compete for the cores, so it compares code changes on a busy machine.
inline double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

// The median of a non-empty list (mean of the middle two for an even count).
inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace angio
