#include "cli/load_volume.h"

#include <functional>

#include "cli/progress_line.h"
#include "io/input_error.h"

namespace angio {

LoadedVolume loadVolumeWithProgress(const std::string& path, const std::string& labels) {
  ReadOptions read;
  read.labelPath = labels;
  read.warn = printWarning;
  ProgressLine loading("loading " + path);
  read.progress = std::ref(loading);
  return readVolume(path, read);
}

}  // namespace angio
