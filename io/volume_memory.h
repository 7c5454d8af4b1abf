#pragma once
// Checking that a volume fits in memory before allocating it, from the header's dimensions alone,
// so a huge or corrupt header gives a clear error instead of bad_alloc or the OOM killer.
#include <cstdint>
#include <filesystem>
#include <optional>

#include <glm/glm.hpp>

namespace angio {

// Memory the system can still hand out: MemAvailable from /proc/meminfo, lowered by a cgroup v2
// limit when one is set. Empty if neither can be read.
std::optional<std::uint64_t> availableMemoryBytes();

// Throws InputError naming `file` if `bytesNeeded` (as a double: corrupt headers may overflow any
// integer) exceeds the available memory, or the dims cannot be indexed by int.
void requireMemory(const std::filesystem::path& file, glm::dvec3 dims, double bytesNeeded);

}  // namespace angio
