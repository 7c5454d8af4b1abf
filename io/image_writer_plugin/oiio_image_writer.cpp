// The image writer module: OpenImageIO behind io/image_writer_plugin.h, so that OpenImageIO and
// the libraries it loads enter the process only when an image is written (io/plugin_module.h).
#include <OpenImageIO/imageio.h>

#include <algorithm>

#include "io/image_writer_plugin.h"

namespace {

OIIO::TypeDesc oiioType(angio::FilePixelType type) {
  switch (type) {
    case angio::FilePixelType::uint8: return OIIO::TypeDesc::UINT8;
    case angio::FilePixelType::uint16: return OIIO::TypeDesc::UINT16;
    case angio::FilePixelType::float32: break;
  }
  return OIIO::TypeDesc::FLOAT;
}

// OIIO error texts may span lines; the caller's messages are one line.
std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

std::string writeImageFile(const angio::ImageFileRequest& request) {
  const OIIO::TypeDesc type = oiioType(request.type);
  OIIO::ImageSpec spec(request.width, request.height, request.channels, type);
  for (const auto& [name, value] : request.attributes) spec.attribute(name, value);
  auto output = OIIO::ImageOutput::create(request.file);
  if (!output) return "cannot create an image writer: " + oneLine(OIIO::geterror());
  if (!output->open(request.file, spec)) return "cannot write: " + oneLine(output->geterror());
  const bool written = output->write_image(type, request.pixels);
  const bool closed = output->close();
  if (!written || !closed) return "write failed: " + oneLine(output->geterror());
  return "";
}

}  // namespace

extern "C" __attribute__((visibility("default"))) void angioray_write_image_file(
    const angio::ImageFileRequest& request, std::string& error) {
  error = writeImageFile(request);
}
