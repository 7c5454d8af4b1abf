#pragma once
// VesselGlyph region shapes as short text (the `--vg-focus` / `--vg-context` options and image
// metadata), all sizes in mm:
//   focus:   "circle:radius=2.0x"  (a factor of the vessel radius) or "circle:radius=3" / "3mm"
//   context: "slab:front=20,back=20[,width=40]" (width = how far the slab reaches sideways from
//            the centerline, each side; "inf" = the thesis's unbounded slab),
//            "tube:radius=20" (mm or a factor such as "4x"), or "none".
// Thesis fig. 5.2: the circle swept along the centerline is the focus, slab or tube the context.
#include <string>

#include "vessel/vessel_glyph.h"

namespace angio {

// Throws std::invalid_argument with a one-line message quoting the spec and saying what is wrong.
TubeRadius parseFocusSpec(const std::string& spec);
// Sets settings.context and settings.slab or settings.contextTube; same errors.
void parseContextSpec(const std::string& spec, VesselGlyphSettings& settings);

// The specs back as text (numbers with up to 10 significant digits), for metadata.
std::string focusSpecText(const TubeRadius& focus);
std::string contextSpecText(const VesselGlyphSettings& settings);

}  // namespace angio
