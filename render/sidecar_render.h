#pragma once
// `angioray render`'s work: render what a RenderSidecar (io/render_sidecar.h) describes - plain
// DVR/MIP, VesselGlyph focus+context (issue 5) or the DVR+CPR hybrid (issue 6 item 5) - export the
// image with its metadata and write the sidecar beside it. The same function serves fresh renders
// and `--params` re-renders, so a sidecar reproduces its image byte for byte.
#include <atomic>
#include <functional>
#include <string>

#include "core/image.h"
#include "core/slice_tiles.h"
#include "core/volume.h"
#include "render/render_sidecar.h"
#include "vessel/centerline.h"

namespace angio {

// For renders of many views (a rotation series) and renders that may be stopped (GUI exports).
struct SidecarRenderOptions {
  const SliceTiles* tiles = nullptr;          // built for params.axis; null: built here
  const std::atomic<bool>* cancel = nullptr;  // set: the fast raycaster stops within a row
  bool* cancelled = nullptr;                  // set to whether it stopped (the image is then partial)
  std::function<void(double)> progress;       // the reference raycaster's progress in [0, 1]
  std::function<void(const std::string&)> warn;  // the hybrid's warnings (e.g. a clipped path)
};

// The image of the sidecar's parameters; `centerlines` (volume frame) are needed iff
// sidecar.vesselGlyph is set. Throws InputError for a bad hybrid path selection.
Image renderSidecarImage(const Volume& volume, const Centerlines& centerlines,
                         const RenderSidecar& sidecar, const SidecarRenderOptions& options = {});

}  // namespace angio
