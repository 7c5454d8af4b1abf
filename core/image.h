#pragma once
// A rendered image: linear RGBA floats (accumulated color C and opacity A of the rendering model),
// row 0 at the top.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace angio {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<glm::vec4> pixels;  // row-major, row 0 at the top

  glm::vec4& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
  const glm::vec4& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

Image makeImage(int width, int height);

// The rendering model's 8-bit output: round(255 clamp(C)) per channel, RGB interleaved.
std::vector<std::uint8_t> toRgb8(const Image& image);

}  // namespace angio
