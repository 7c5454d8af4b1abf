#pragma once
// A generated phantom with its ground-truth centerlines mapped into the volume's frame: what the
// render tests feed to PreparedScene and the independent paths they compare it with.
#include <utility>

#include "phantom/phantom.h"
#include "vessel/centerline.h"

namespace angio::test_support {

struct PhantomInVolumeFrame {
  Volume volume;
  Centerlines centerlines;  // volume frame
};

inline PhantomInVolumeFrame phantomInVolumeFrame(glm::ivec3 dims) {
  PhantomOptions options;
  options.style = PhantomStyle::simple;
  options.dims = dims;
  Phantom phantom = generatePhantom(options);
  Centerlines centerlines = toVolumeFrame(phantom.centerlines, phantom.volume);
  return {std::move(phantom.volume), std::move(centerlines)};
}

}  // namespace angio::test_support
