#pragma once
// Small timing helpers shared by the benchmarks: wall-clock milliseconds and medians.
#include <algorithm>
#include <chrono>
#include <vector>

namespace angio {

using BenchClock = std::chrono::steady_clock;

inline double msSince(BenchClock::time_point start) {
  return std::chrono::duration<double, std::milli>(BenchClock::now() - start).count();
}

// The median of a non-empty list (mean of the middle two for an even count).
inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace angio
