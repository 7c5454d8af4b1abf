#include "io/volume_memory.h"

#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

#include "io/input_error.h"

namespace angio {

namespace {

std::optional<std::uint64_t> memInfoAvailable() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kilobytes = 0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit) {
    if (key == "MemAvailable:") return kilobytes * 1024;
  }
  return std::nullopt;
}

std::optional<std::uint64_t> cgroupHeadroom() {
  std::ifstream maxFile("/sys/fs/cgroup/memory.max"), currentFile("/sys/fs/cgroup/memory.current");
  std::string limit;
  std::uint64_t current = 0;
  if (!(maxFile >> limit) || limit == "max" || !(currentFile >> current)) return std::nullopt;
  try {
    const std::uint64_t max = std::stoull(limit);
    return max > current ? max - current : 0;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::string gigabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
  return text;
}

std::string dimsText(glm::dvec3 dims) {
  char text[96];
  std::snprintf(text, sizeof text, "%.0f x %.0f x %.0f", dims.x, dims.y, dims.z);
  return text;
}

}  // namespace

std::optional<std::uint64_t> availableMemoryBytes() {
  const auto system = memInfoAvailable();
  const auto cgroup = cgroupHeadroom();
  if (system && cgroup) return std::min(*system, *cgroup);
  return system ? system : cgroup;
}

void requireMemory(const std::filesystem::path& file, glm::dvec3 dims, double bytesNeeded) {
  const double largestInt = double(std::numeric_limits<int>::max());
  if (dims.x > largestInt || dims.y > largestInt || dims.z > largestInt)
    throw InputError(file, "dimensions " + dimsText(dims) + " are too large");
  const auto available = availableMemoryBytes();
  if (available && bytesNeeded > double(*available))
    throw InputError(file, dimsText(dims) + " voxels need " + gigabytes(bytesNeeded) +
                               " of memory to load but only " + gigabytes(double(*available)) +
                               " is available");
}

}  // namespace angio
