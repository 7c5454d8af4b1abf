#include "core/image.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

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

double psnrDb(const Image& image, const Image& exact) {
  if (image.width != exact.width || image.height != exact.height)
    throw std::invalid_argument("psnrDb: images of different sizes");
  const std::vector<std::uint8_t> a = toRgb8(image), b = toRgb8(exact);
  double squares = 0;
  for (std::size_t n = 0; n < a.size(); ++n)
    squares += double(int(a[n]) - int(b[n])) * (int(a[n]) - int(b[n]));
  if (squares == 0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(255.0 * 255.0 * double(a.size()) / squares);
}

}  // namespace angio
