#pragma once
// The parameters of a render as key/value metadata for exported images (and their sidecars):
// everything needed to say how an image was made.
#include <optional>
#include <string>

#include "core/render_params.h"
#include "io/image_export.h"

namespace angio {

struct RenderDescription {
  std::string dataset;               // file or folder the volume came from
  std::string transferFunction;      // TF name
  std::optional<Quality> quality;    // the level the sampling started from, if any
  RenderParams params;
};

ImageMetadata renderMetadata(const RenderDescription& description);

}  // namespace angio
