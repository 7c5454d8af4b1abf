#pragma once
// The "IxJxK" voxel-count option of `phantom`, `demo`, `bench` and `gui`.
#include <string>

#include <glm/glm.hpp>

namespace angio {

// Parses "IxJxK" (e.g. "512x512x1200") into voxel counts; throws on anything else.
glm::ivec3 parseSize(const std::string& text);

}  // namespace angio
