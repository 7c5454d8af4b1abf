#pragma once
// Shared modules of angioray's own that the process opens at first use (dlopen) instead of at
// start. OpenImageIO and OpenCV's videoio bring some 220 more shared libraries (FFmpeg, GDAL, HDF5,
// ...) that cost over 100 MB of resident memory in every process that links them, though only
// image and movie export use them; linked into the executable, that memory sat under every render
// and load. The modules live beside the executable, or in the build tree (ANGIORAY_PLUGIN_DIR).
#include <string>

namespace angio {

// The address of `symbol` in the module file `moduleName` (e.g. "angioray_image_writer.so"),
// opening the module on the first call. Throws std::runtime_error (one line) if the module or
// the symbol cannot be found.
void* pluginSymbol(const std::string& moduleName, const char* symbol);

// The same, as the function type the caller expects.
template <typename Function>
Function pluginFunction(const std::string& moduleName, const char* symbol) {
  return reinterpret_cast<Function>(pluginSymbol(moduleName, symbol));
}

}  // namespace angio
