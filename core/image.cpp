#include "core/image.h"

#include <algorithm>
#include <cmath>

namespace angio {

Image makeImage(int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.pixels.assign(std::size_t(width) * height, glm::vec4(0.f));
  return image;
}

std::vector<std::uint8_t> toRgb8(const Image& image) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(image.pixels.size() * 3);
  for (const glm::vec4& p : image.pixels) {
    for (int c = 0; c < 3; ++c)
      bytes.push_back(std::uint8_t(std::lround(255.f * std::clamp(p[c], 0.f, 1.f))));
  }
  return bytes;
}

}  // namespace angio
