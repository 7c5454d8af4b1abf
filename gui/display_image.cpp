#include "gui/display_image.h"

#include <algorithm>

namespace angio {

namespace {

Rgb8Image halved(const Rgb8Image& image) {
  const int w = image.width, h = image.height;
  Rgb8Image half;
  half.width = std::max(w / 2, 1);
  half.height = std::max(h / 2, 1);
  half.rgb.resize(std::size_t(half.width) * half.height * 3);
  const auto at = [&](int x, int y, int c) { return int(image.rgb[(std::size_t(y) * w + x) * 3 + c]); };
  for (int y = 0; y < half.height; ++y) {
    const int y0 = std::min(2 * y, h - 1), y1 = std::min(2 * y + 1, h - 1);
    for (int x = 0; x < half.width; ++x) {
      const int x0 = std::min(2 * x, w - 1), x1 = std::min(2 * x + 1, w - 1);
      for (int c = 0; c < 3; ++c) {
        const int sum = at(x0, y0, c) + at(x1, y0, c) + at(x0, y1, c) + at(x1, y1, c);
        half.rgb[(std::size_t(y) * half.width + x) * 3 + c] = std::uint8_t((sum + 2) / 4);
      }
    }
  }
  return half;
}

}  // namespace

std::vector<Rgb8Image> halvedLevels(const Rgb8Image& image) {
  std::vector<Rgb8Image> levels;
  if (image.width <= 0 || image.height <= 0) return levels;
  const Rgb8Image* source = &image;
  while (source->width > 1 || source->height > 1) {
    levels.push_back(halved(*source));
    source = &levels.back();
  }
  return levels;
}

std::shared_ptr<const DisplayImage> makeDisplayImage(const Image& image) {
  auto display = std::make_shared<DisplayImage>();
  display->levels.push_back({image.width, image.height, toRgb8(image)});
  std::vector<Rgb8Image> halves = halvedLevels(display->levels.front());
  for (Rgb8Image& half : halves) display->levels.push_back(std::move(half));
  return display;
}

}  // namespace angio
