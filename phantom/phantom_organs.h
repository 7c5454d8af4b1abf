#pragma once
// What the realistic phantom adds to the simple one's anatomy (phantom_anatomy.h): abdominal organs
// at arterial-phase (or portal-venous) densities (liver, spleen, pancreas, unopacified bladder), psoas muscles, small
// bowel loops and colon (enhancing wall around fluid or gas), and hundreds of small contrast-filled
// branches (1-3 mm) off the arterial tree into the muscles and inside the organs. Real CT owes much
// of its rendering cost to such tissue: its densities sit on the low-opacity ramp of vessel
// transfer functions, so empty-space skipping finds less to skip and rays saturate later.
// The layout is fixed (its random choices come from a fixed seed), like the rest of the anatomy.
#include <functional>

#include "phantom/phantom_anatomy.h"
#include "phantom/phantom_arteries.h"

namespace angio::phantom {

// lumenHu(distance from the aortic root, mm): the contrast density of the tree at that distance.
// `style` (realistic or portalVenous) is the contrast phase: the organs' densities, and in the
// portal-venous phase the enhanced veins (portal system, renal veins, cava, iliac, femoral,
// popliteal and paired tibial veins).
void addRealisticTissue(Anatomy& anatomy, const ArterialTree& tree,
                        const std::function<double(double)>& lumenHu, PhantomStyle style);

}  // namespace angio::phantom
