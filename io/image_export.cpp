#include "io/image_export.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "io/atomic_write.h"
#include "io/input_error.h"
#include "io/lowercase.h"

#ifndef ANGIORAY_VERSION
#define ANGIORAY_VERSION "unknown"
#endif

namespace angio {

namespace fs = std::filesystem;

namespace {

enum class ExportFormat { png8, tiff16, exrFloat };

// What goes to OpenImageIO: channel count, pixel type and the interleaved pixel bytes.
struct EncodedPixels {
  int channels = 0;
  OIIO::TypeDesc type;
  std::vector<std::uint8_t> bytes;
};

ExportFormat formatOf(const fs::path& path) {
  const std::string extension = lowercase(path.extension().string());
  if (extension == ".png") return ExportFormat::png8;
  if (extension == ".tif" || extension == ".tiff") return ExportFormat::tiff16;
  if (extension == ".exr") return ExportFormat::exrFloat;
  throw InputError(path, "unknown image format \"" + path.extension().string() +
                             "\" (use .png, .tif, .tiff or .exr)");
}

template <typename T, typename Allocator>
std::vector<std::uint8_t> asBytes(const std::vector<T, Allocator>& values) {
  const auto* first = reinterpret_cast<const std::uint8_t*>(values.data());
  return std::vector<std::uint8_t>(first, first + values.size() * sizeof(T));
}

// 16-bit output, the 8-bit rule of the rendering model at 16 bits: round(65535 clamp(C)).
std::vector<std::uint16_t> toRgb16(const Image& image) {
  std::vector<std::uint16_t> values;
  values.reserve(image.pixels.size() * 3);
  for (const glm::vec4& p : image.pixels) {
    for (int c = 0; c < 3; ++c)
      values.push_back(std::uint16_t(std::lround(65535.f * std::clamp(p[c], 0.f, 1.f))));
  }
  return values;
}

EncodedPixels encode(const Image& image, ExportFormat format) {
  switch (format) {
    case ExportFormat::png8: return {3, OIIO::TypeDesc::UINT8, toRgb8(image)};
    case ExportFormat::tiff16: return {3, OIIO::TypeDesc::UINT16, asBytes(toRgb16(image))};
    case ExportFormat::exrFloat: break;
  }
  // Linear C and A as rendered (C is already premultiplied by A, as EXR expects).
  static_assert(sizeof(glm::vec4) == 4 * sizeof(float));
  return {4, OIIO::TypeDesc::FLOAT, asBytes(image.pixels)};
}

std::string describe(const ImageMetadata& metadata) {
  std::string description;
  for (const auto& [key, value] : metadata)
    description += (description.empty() ? "" : "; ") + key + "=" + value;
  return description;
}

OIIO::ImageSpec makeSpec(const Image& image, const EncodedPixels& pixels,
                         const ImageMetadata& metadata) {
  OIIO::ImageSpec spec(image.width, image.height, pixels.channels, pixels.type);
  spec.attribute("Software", std::string("angioray ") + ANGIORAY_VERSION);
  if (!metadata.empty()) spec.attribute("ImageDescription", describe(metadata));
  // Formats without free-form metadata (TIFF) silently drop these; PNG and EXR keep them.
  for (const auto& [key, value] : metadata) spec.attribute("angioray:" + key, value);
  return spec;
}

// OIIO error texts may span lines; InputError messages are one line.
std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

void checkWritable(const Image& image, const fs::path& path) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != std::size_t(image.width) * std::size_t(image.height)) {
    throw InputError(path, "cannot export an empty image (" + std::to_string(image.width) + "x" +
                               std::to_string(image.height) + ")");
  }
  const fs::path directory = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code error;
  if (!fs::is_directory(directory, error))
    throw InputError(path, "directory " + directory.string() + " does not exist");
}

// Writes to `file` (the temporary name); errors name `target`, the file the user asked for.
void writeWithOiio(const fs::path& file, const fs::path& target, const OIIO::ImageSpec& spec,
                   const EncodedPixels& pixels) {
  auto output = OIIO::ImageOutput::create(file.string());
  if (!output) throw InputError(target, "cannot create an image writer: " + oneLine(OIIO::geterror()));
  if (!output->open(file.string(), spec))
    throw InputError(target, "cannot write: " + oneLine(output->geterror()));
  const bool written = output->write_image(pixels.type, pixels.bytes.data());
  const bool closed = output->close();
  if (!written || !closed) throw InputError(target, "write failed: " + oneLine(output->geterror()));
}

}  // namespace

void exportImage(const Image& image, const fs::path& path, const ImageMetadata& metadata) {
  const ExportFormat format = formatOf(path);
  checkWritable(image, path);
  const EncodedPixels pixels = encode(image, format);
  const OIIO::ImageSpec spec = makeSpec(image, pixels, metadata);
  try {
    writeAtomically(path,
                    [&](const fs::path& tempPath) { writeWithOiio(tempPath, path, spec, pixels); });
  } catch (const fs::filesystem_error& error) {
    // The rename over the target failed (e.g. the target is a directory).
    throw InputError(path, "cannot write: " + error.code().message());
  }
}

}  // namespace angio
