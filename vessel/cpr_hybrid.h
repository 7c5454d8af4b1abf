#pragma once
// The DVR+CPR hybrid (thesis sec. 5.2.2, fig. 5.4 and 5.5): DVR of the context
// with the focus cut out in image space, and the projected CPR (vessel/cpr_layout.h, which
// registers pixel for pixel with the DVR image of the same view) composited into the cut.
//
// The cut is the focus's image-space footprint: the pixels whose ray meets the focus region
// (RayRegions of vessel/vessel_glyph.h). Inside it the image is the CPR wherever the CPR samples
// the pixel (elsewhere, e.g. beyond a path's ends, the DVR image stays); with a transition band of width T mm the CPR fades out over T beyond the cut's edge
// (weight 1 - distance / T, distance in mm in the image plane from the nearest footprint pixel,
// thesis fig. 5.5 b), so the lumen slice blends into its context; T = 0 gives the hard edge of
// fig. 5.5 a. Elsewhere the DVR image is kept unchanged. Pure function of images, no files.
#include <cstdint>
#include <vector>

#include "core/image.h"
#include "core/region_intervals.h"
#include "core/volume.h"
#include "vessel/cpr_display.h"
#include "vessel/cpr_layout.h"

namespace angio {

// 1 where the pixel's ray has a focus interval, row-major regions.width x regions.height.
std::vector<std::uint8_t> focusFootprint(const RayRegions& regions);

struct HybridCompositing {
  double transitionMm = 0;  // T, >= 0
  double pixelMm = 1;       // D, the images' pixel size (mm)
};

// dvr: the VesselGlyph DVR (its cut pixels are replaced); cpr: the projected CPR shown as color (displayCpr: A = 0
// where not sampled, else 1), same size; footprint as focusFootprint. Throws std::invalid_argument
// on mismatched sizes or a negative transition.
Image compositeHybrid(const Image& dvr, const Image& cpr, const std::vector<std::uint8_t>& footprint,
                      const HybridCompositing& settings);

// The same hybrid in place, for a projected CPR `layout` (laid out in the DVR's view): equal to
// compositeHybrid(dvr, displayCpr(layout, resampleCpr(volume, layout), display), footprint,
// settings) with the display's marker and ruler off, but only the pixels the CPR shows in are
// resampled and colored, so its cost follows the footprint, not the whole image. Throws as
// compositeHybrid.
void compositeCprInPlace(Image& dvr, const Volume& volume, const CprLayout& layout,
                         const std::vector<std::uint8_t>& footprint, const CprDisplay& display,
                         const HybridCompositing& settings);

}  // namespace angio
