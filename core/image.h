#pragma once
// A rendered image: linear RGBA floats (accumulated color C and opacity A of the rendering model),
// row 0 at the top.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/uninitialised_allocator.h"

namespace angio {

// Row-major, row 0 at the top. resize() leaves new pixels unset; assign() sets them.
using Pixels = UninitialisedVector<glm::vec4>;

struct Image {
  int width = 0;
  int height = 0;
  Pixels pixels;

  glm::vec4& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
  const glm::vec4& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

// An image of transparent black pixels.
Image makeImage(int width, int height);

// The rendering model's 8-bit output: round(255 clamp(C)) per channel, RGB interleaved.
std::vector<std::uint8_t> toRgb8(const Image& image);

// Peak signal-to-noise ratio of `image` against `exact` in dB, over the 8-bit RGB output (what is
// seen and saved): 10 log10(255^2 / mean squared difference); infinite for equal output. The
// measure of the approximations (rendering model). Throws std::invalid_argument for other sizes.
double psnrDb(const Image& image, const Image& exact);

}  // namespace angio
