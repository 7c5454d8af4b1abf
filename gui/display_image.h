#pragma once
// An image in the form the UI shows it: 8-bit RGB (the rendering model's round(255 clamp(C))) and
// its mipmap levels, so a large high-quality image shrunk to the window does not alias and
// zooming in shows every pixel. The app makes one per rendered frame on the renderer's worker
// (ProgressiveCallbacks::makeDisplay), so the UI thread only uploads it.
#include <cstdint>
#include <memory>
#include <vector>

#include "core/image.h"
#include "render/progressive_renderer.h"

namespace angio {

// 8-bit RGB pixels, rows top to bottom, no padding.
struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

struct DisplayImage {
  std::vector<Rgb8Image> levels;  // [0] the image itself, then each half of the one before, to 1x1
};

// The image halved again and again (2x2 box filter, sizes floor(n / 2), at least 1) down to 1x1,
// starting with the first half: the mipmap levels above level 0 of a texture.
std::vector<Rgb8Image> halvedLevels(const Rgb8Image& image);

std::shared_ptr<const DisplayImage> makeDisplayImage(const Image& image);

}  // namespace angio
