#pragma once
// The "IxJxK" voxel-count and style options of `phantom`, `demo`, `bench` and `gui`.
#include <string>

#include <glm/glm.hpp>

#include "phantom/phantom.h"

namespace angio {

// Parses "IxJxK" (e.g. "512x512x1200") into voxel counts; throws on anything else.
glm::ivec3 parseSize(const std::string& text);

// Parses a phantom style name ("realistic" or "simple"); throws on anything else.
PhantomStyle parseStyle(const std::string& name);

}  // namespace angio
