#pragma once
// The reference raycaster: the rendering model, sample by sample, nothing skipped. Every
// accelerated renderer is tested against it. Multi-threaded over image rows; each pixel is
// computed by one thread from the same inputs, so the bytes do not depend on the thread count.
#include <functional>

#include "core/compositing.h"
#include "core/image.h"
#include "core/render_params.h"
#include "core/transfer_function.h"
#include "core/volume.h"

namespace angio {

// progress(fraction of rows done) may be called from any worker thread; may be empty.
Image renderReference(const Volume& volume, const TfTable& table, const RenderParams& params,
                      const std::function<void(double)>& progress = {});

// VesselGlyph: each region of each ray with its own TF (core/compositing.h RegionTables).
Image renderReference(const Volume& volume, const RegionTables& tables, const RenderParams& params,
                      const std::function<void(double)>& progress = {});

}  // namespace angio
