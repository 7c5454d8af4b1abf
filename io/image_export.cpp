#include "io/image_export.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <variant>
#include <vector>

#include "io/atomic_write.h"
#include "io/image_writer_plugin.h"
#include "io/input_error.h"
#include "io/lowercase.h"
#include "io/plugin_module.h"

#ifndef ANGIORAY_VERSION
#define ANGIORAY_VERSION "unknown"
#endif

namespace angio {

namespace fs = std::filesystem;

namespace {

enum class ExportFormat { png8, tiff16, exrFloat };

// What goes to the writer: channel count, pixel type and the interleaved values: converted for 8
// and 16 bits, the image's own floats for EXR (a copy would add 16 bytes a pixel to the peak).
struct EncodedPixels {
  int channels = 0;
  FilePixelType type = FilePixelType::uint8;
  std::variant<std::vector<std::uint8_t>, std::vector<std::uint16_t>, const glm::vec4*> values;

  const void* data() const {
    return std::visit(
        [](const auto& v) -> const void* {
          if constexpr (std::is_pointer_v<std::decay_t<decltype(v)>>) return v;
          else return v.data();
        },
        values);
  }
};

ExportFormat formatOf(const fs::path& path) {
  const std::string extension = lowercase(path.extension().string());
  if (extension == ".png") return ExportFormat::png8;
  if (extension == ".tif" || extension == ".tiff") return ExportFormat::tiff16;
  if (extension == ".exr") return ExportFormat::exrFloat;
  throw InputError(path, "unknown image format \"" + path.extension().string() +
                             "\" (use .png, .tif, .tiff or .exr)");
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
    case ExportFormat::png8: return {3, FilePixelType::uint8, toRgb8(image)};
    case ExportFormat::tiff16: return {3, FilePixelType::uint16, toRgb16(image)};
    case ExportFormat::exrFloat: break;
  }
  // Linear C and A as rendered (C is already premultiplied by A, as EXR expects).
  static_assert(sizeof(glm::vec4) == 4 * sizeof(float));
  return {4, FilePixelType::float32, image.pixels.data()};
}

std::string describe(const ImageMetadata& metadata) {
  std::string description;
  for (const auto& [key, value] : metadata)
    description += (description.empty() ? "" : "; ") + key + "=" + value;
  return description;
}

ImageFileRequest makeRequest(const Image& image, const EncodedPixels& pixels,
                             const ImageMetadata& metadata) {
  ImageFileRequest request;
  request.width = image.width;
  request.height = image.height;
  request.channels = pixels.channels;
  request.type = pixels.type;
  request.pixels = pixels.data();
  request.attributes.emplace_back("Software", std::string("angioray ") + ANGIORAY_VERSION);
  if (!metadata.empty()) request.attributes.emplace_back("ImageDescription", describe(metadata));
  // Formats without free-form metadata (TIFF) silently drop these; PNG and EXR keep them.
  for (const auto& [key, value] : metadata) request.attributes.emplace_back("angioray:" + key, value);
  return request;
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

// Writes to `file` (the temporary name) through the image writer module (OpenImageIO, opened at
// the first export); errors name `target`, the file the user asked for.
void writeWithModule(const fs::path& file, const fs::path& target, ImageFileRequest request) {
  // The module opens once (dlopen counts further opens); each export only looks the symbol up.
  WriteImageFile writeImageFile = nullptr;
  try {
    writeImageFile = pluginFunction<WriteImageFile>(kImageWriterModule, kWriteImageFileSymbol);
  } catch (const std::runtime_error& error) {  // a copied angioray without its module
    throw InputError(target, error.what());
  }
  request.file = file.string();
  std::string error;
  writeImageFile(request, error);
  if (!error.empty()) throw InputError(target, error);
}

}  // namespace

void exportImage(const Image& image, const fs::path& path, const ImageMetadata& metadata) {
  const ExportFormat format = formatOf(path);
  checkWritable(image, path);
  const EncodedPixels pixels = encode(image, format);
  const ImageFileRequest request = makeRequest(image, pixels, metadata);
  try {
    writeAtomically(path, [&](const fs::path& tempPath) { writeWithModule(tempPath, path, request); });
  } catch (const fs::filesystem_error& error) {
    // The rename over the target failed (e.g. the target is a directory).
    throw InputError(path, "cannot write: " + error.code().message());
  }
}

}  // namespace angio
