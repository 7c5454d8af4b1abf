#pragma once
// An image file's decoded 8-bit pixels, for tests that look at what the command line wrote.
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>

namespace angio::test_support {

struct Pixels {
  int width = 0, height = 0, channels = 0;
  std::vector<unsigned char> values;  // row by row, channels interleaved

  const unsigned char* at(int x, int y) const {
    return values.data() + (std::size_t(y) * width + x) * channels;
  }
};

inline Pixels pixelsOf(const std::string& file) {
  OIIO::ImageBuf image(file);
  EXPECT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::UINT8)) << file;
  const OIIO::ImageSpec& spec = image.spec();
  Pixels pixels{spec.width, spec.height, spec.nchannels, {}};
  pixels.values.resize(std::size_t(spec.width) * spec.height * spec.nchannels);
  image.get_pixels(image.roi(), OIIO::TypeDesc::UINT8, pixels.values.data());
  return pixels;
}

}  // namespace angio::test_support
