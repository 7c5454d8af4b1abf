#pragma once
// Image export through OpenImageIO, format by extension: .png (8-bit RGB, the rendering model's
// round(255 clamp(C))), .tif/.tiff (16-bit RGB), .exr (float RGBA, linear C and A). The render
// parameters go into the file's metadata. Atomic: temp name, then rename. Throws InputError.
#include <filesystem>
#include <map>
#include <string>

#include "core/image.h"

namespace angio {

// Metadata key -> value, written as "angioray:<key>" attributes (and a PNG/TIFF description).
using ImageMetadata = std::map<std::string, std::string>;

void exportImage(const Image& image, const std::filesystem::path& path,
                 const ImageMetadata& metadata = {});

}  // namespace angio
