#pragma once
// `angioray render`'s work: render what a RenderSidecar (io/render_sidecar.h) describes - plain
// DVR/MIP, VesselGlyph focus+context (issue 5) or the DVR+CPR hybrid (issue 6 item 5) - export the
// image with its metadata and write the sidecar beside it. The same function serves fresh renders
// and `--params` re-renders, so a sidecar reproduces its image byte for byte.
#include <filesystem>

#include "core/image.h"
#include "core/volume.h"
#include "io/render_sidecar.h"
#include "vessel/centerline.h"

namespace angio {

// The image of the sidecar's parameters; `centerlines` (volume frame) are needed iff
// sidecar.vesselGlyph is set. Throws std::invalid_argument for a bad hybrid path selection.
Image renderSidecarImage(const Volume& volume, const Centerlines& centerlines,
                         const RenderSidecar& sidecar);

// Loads the volume (and centerlines), renders, exports to `out` and writes sidecarPathFor(out)
// with image = out. Returns the render time in seconds.
double renderSidecarToFile(RenderSidecar sidecar, const std::filesystem::path& out);

}  // namespace angio
