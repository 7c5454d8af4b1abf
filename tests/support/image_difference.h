#pragma once
// Checking rendered images in tests: the largest difference of any channel of any pixel, and
// whether an image shows anything at all.
#include <algorithm>
#include <cmath>

#include "core/image.h"

namespace angio::test_support {

inline float maxChannelDifference(const Image& a, const Image& b) {
  float worst = 0.f;
  for (std::size_t n = 0; n < a.pixels.size(); ++n)
    for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(a.pixels[n][c] - b.pixels[n][c]));
  return worst;
}

// Some pixel is more than half opaque: the image shows something, so comparing it proves something.
inline bool showsSomething(const Image& image) {
  for (const glm::vec4& pixel : image.pixels)
    if (pixel.a > 0.5f) return true;
  return false;
}

}  // namespace angio::test_support
