// Image export: pixel values read back exactly per format, metadata on read-back, and the
// InputError / atomic-write guarantees.
#include "io/image_export.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

namespace fs = std::filesystem;
using test_support::expectInputError;
using test_support::fileBytes;

// An analytic pattern: horizontal and vertical gradients, a checker in blue, and values outside
// [0, 1] (negative and > 1) that the integer formats must clamp and EXR must keep.
Image gradientImage(int width = 37, int height = 23) {
  Image image = makeImage(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float u = (x + 0.5f) / width, v = (y + 0.5f) / height;
      image.at(x, y) =
          glm::vec4(1.3f * u - 0.15f, v * v, (x + y) % 2 ? 0.25f : 0.7503f, 0.5f + 0.5f * u * v);
    }
  }
  return image;
}

struct ReadBack {
  OIIO::ImageSpec spec;
  std::vector<float> floats;          // EXR
  std::vector<std::uint8_t> bytes;    // PNG
  std::vector<std::uint16_t> shorts;  // TIFF
};

ReadBack readBack(const fs::path& file) {
  ReadBack result;
  auto input = OIIO::ImageInput::open(file.string());
  if (!input) {
    ADD_FAILURE() << "cannot open " << file << ": " << OIIO::geterror();
    return result;
  }
  result.spec = input->spec();
  const std::size_t values = result.spec.image_pixels() * result.spec.nchannels;
  bool ok = false;
  if (result.spec.format == OIIO::TypeDesc::UINT8) {
    result.bytes.resize(values);
    ok = input->read_image(0, 0, 0, -1, OIIO::TypeDesc::UINT8, result.bytes.data());
  } else if (result.spec.format == OIIO::TypeDesc::UINT16) {
    result.shorts.resize(values);
    ok = input->read_image(0, 0, 0, -1, OIIO::TypeDesc::UINT16, result.shorts.data());
  } else {
    result.floats.resize(values);
    ok = input->read_image(0, 0, 0, -1, OIIO::TypeDesc::FLOAT, result.floats.data());
  }
  EXPECT_TRUE(ok) << input->geterror();
  input->close();
  return result;
}

// Every channel of every pixel of `image`, read back as `values` (`channels` a pixel), equals
// `expected(the channel's value in the image)`.
template <class T, class Expected>
void expectEveryChannel(const std::vector<T>& values, const Image& image, int channels,
                        const Expected& expected) {
  ASSERT_EQ(values.size(), image.pixels.size() * channels);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    for (int c = 0; c < channels; ++c)
      ASSERT_EQ(values[channels * i + c], expected(image.pixels[i][c]))
          << "pixel " << i << " channel " << c;
  }
}

class ImageExportTest : public test_support::TempFolderTest {
 protected:
  // Exports `image` with the metadata to the file `name` in the folder and reads it back.
  ReadBack exportAndReadBack(const Image& image, const std::string& name) const {
    const fs::path file = dir_ / name;
    exportImage(image, file, metadata_);
    return readBack(file);
  }

  const ImageMetadata metadata_{{"angle", "30"}, {"tf", "cta-vessels"}, {"quality", "high"}};
};

TEST_F(ImageExportTest, PngIsEightBitRgbEqualToToRgb8) {
  const Image image = gradientImage();
  const ReadBack read = exportAndReadBack(image, "out.png");
  EXPECT_EQ(read.spec.width, image.width);
  EXPECT_EQ(read.spec.height, image.height);
  EXPECT_EQ(read.spec.nchannels, 3);
  EXPECT_EQ(read.spec.format, OIIO::TypeDesc::UINT8);
  const std::vector<std::uint8_t> expected = toRgb8(image);
  EXPECT_EQ(read.bytes, expected);
  // Spot-check the rule itself, independent of toRgb8: round(255 clamp(C)).
  const glm::vec4 corner = image.at(image.width - 1, 0);
  EXPECT_EQ(read.bytes[3 * (image.width - 1) + 0], 255);  // 1.3u - 0.15 > 1: clamped
  EXPECT_EQ(read.bytes[0], 0);                            // negative: clamped
  EXPECT_EQ(read.bytes[3 * (image.width - 1) + 1], std::lround(255 * corner.g));
  EXPECT_EQ(read.bytes[2], 191);  // 0.7503 * 255 = 191.33
}

TEST_F(ImageExportTest, TiffIsSixteenBitRgb) {
  const Image image = gradientImage();
  const ReadBack read = exportAndReadBack(image, "out.tiff");
  EXPECT_EQ(read.spec.nchannels, 3);
  EXPECT_EQ(read.spec.format, OIIO::TypeDesc::UINT16);
  ASSERT_NO_FATAL_FAILURE(expectEveryChannel(read.shorts, image, 3, [](float value) {
    return std::round(65535.0 * std::clamp(double(value), 0.0, 1.0));
  }));
  EXPECT_EQ(read.shorts[2], 49171);  // 0.7503 * 65535 = 49170.9
  EXPECT_NE(read.spec.get_string_attribute("ImageDescription").find("angle=30"), std::string::npos);
}

TEST_F(ImageExportTest, TifExtensionAlsoWorksCaseInsensitively) {
  const fs::path file = dir_ / "OUT.TIF";
  exportImage(gradientImage(), file);
  EXPECT_EQ(readBack(file).spec.format, OIIO::TypeDesc::UINT16);
}

TEST_F(ImageExportTest, ExrIsFloatRgbaKeptExactly) {
  const Image image = gradientImage();
  const ReadBack read = exportAndReadBack(image, "out.exr");
  EXPECT_EQ(read.spec.nchannels, 4);
  EXPECT_EQ(read.spec.format, OIIO::TypeDesc::FLOAT);
  ASSERT_NO_FATAL_FAILURE(expectEveryChannel(read.floats, image, 4, [](float value) { return value; }));
  EXPECT_LT(read.floats[0], 0.f);  // unclamped
  EXPECT_EQ(read.spec.channelnames, (std::vector<std::string>{"R", "G", "B", "A"}));
}

TEST_F(ImageExportTest, PngAndExrCarryTheMetadata) {
  for (const char* name : {"meta.png", "meta.exr"}) {
    SCOPED_TRACE(name);
    const OIIO::ImageSpec spec = exportAndReadBack(gradientImage(), name).spec;
    EXPECT_EQ(spec.get_string_attribute("angioray:angle"), "30");
    EXPECT_EQ(spec.get_string_attribute("angioray:tf"), "cta-vessels");
    EXPECT_EQ(spec.get_string_attribute("ImageDescription"), "angle=30; quality=high; tf=cta-vessels");
    EXPECT_EQ(spec.get_string_attribute("Software").substr(0, 9), "angioray ");
  }
}

TEST_F(ImageExportTest, OverwritesAnExistingFileAndLeavesNoTemporaries) {
  const fs::path file = dir_ / "again.png";
  exportImage(makeImage(4, 4), file);
  Image white = makeImage(4, 4);
  for (glm::vec4& p : white.pixels) p = glm::vec4(1.f);
  exportImage(white, file);
  const ReadBack read = readBack(file);
  EXPECT_EQ(read.bytes, std::vector<std::uint8_t>(4 * 4 * 3, 255));
  EXPECT_EQ(filesInDir(), std::vector<std::string>{"again.png"});
}

TEST_F(ImageExportTest, UnknownExtensionIsAnInputError) {
  const fs::path file = dir_ / "out.jpg2";
  expectInputError([&] { exportImage(gradientImage(), file); }, file, "unknown image format");
  const fs::path noExtension = dir_ / "out";
  expectInputError([&] { exportImage(gradientImage(), noExtension); }, noExtension,
                   "unknown image format");
  EXPECT_TRUE(filesInDir().empty());
}

TEST_F(ImageExportTest, MissingDirectoryIsAnInputError) {
  const fs::path file = dir_ / "missing" / "out.png";
  expectInputError([&] { exportImage(gradientImage(), file); }, file, "does not exist");
  EXPECT_FALSE(fs::exists(dir_ / "missing"));
}

TEST_F(ImageExportTest, EmptyImageIsAnInputError) {
  const fs::path file = dir_ / "empty.exr";
  expectInputError([&] { exportImage(Image{}, file); }, file, "empty image (0x0)");
  Image inconsistent;  // claims 3x3 but holds no pixels
  inconsistent.width = inconsistent.height = 3;
  expectInputError([&] { exportImage(inconsistent, file); }, file, "empty image");
}

TEST_F(ImageExportTest, FailedExportKeepsTheExistingFileByteIdentical) {
  const fs::path file = dir_ / "keep.png";
  exportImage(gradientImage(), file, metadata_);
  const std::string before = fileBytes(file);
  ASSERT_FALSE(before.empty());
  EXPECT_THROW(exportImage(makeImage(0, 0), file), InputError);
  EXPECT_EQ(fileBytes(file), before);
  EXPECT_EQ(filesInDir(), std::vector<std::string>{"keep.png"});
}

TEST_F(ImageExportTest, FailureAfterWritingRemovesTheTemporary) {
  // The target is a non-empty directory: the image is written to the temporary name, then the
  // rename over the target fails. The directory must survive and no temporary may remain.
  const fs::path file = dir_ / "taken.png";
  fs::create_directories(file);
  std::ofstream(file / "inside.txt") << "keep me";
  expectInputError([&] { exportImage(gradientImage(), file); }, file, "cannot write");
  EXPECT_EQ(fileBytes(file / "inside.txt"), "keep me");
  EXPECT_EQ(filesInDir(), std::vector<std::string>{"taken.png"});
}

}  // namespace
}  // namespace angio
