#pragma once
// The one call between io/image_export.cpp and the image writer module
// (io/image_writer_plugin/, OpenImageIO), opened at the first export (io/plugin_module.h).
#include <string>
#include <utility>
#include <vector>

namespace angio {

inline constexpr char kImageWriterModule[] = "angioray_image_writer.so";
inline constexpr char kWriteImageFileSymbol[] = "angioray_write_image_file";

enum class FilePixelType { uint8, uint16, float32 };

// One image file to write: its pixels interleaved, row 0 at the top, the format by the file's
// extension, the attributes as string-valued metadata.
struct ImageFileRequest {
  std::string file;
  int width = 0;
  int height = 0;
  int channels = 0;
  FilePixelType type = FilePixelType::uint8;
  const void* pixels = nullptr;
  std::vector<std::pair<std::string, std::string>> attributes;
};

// Writes the file; leaves `error` empty or sets it to what failed, one line ("cannot write: ...").
using WriteImageFile = void (*)(const ImageFileRequest& request, std::string& error);

}  // namespace angio
