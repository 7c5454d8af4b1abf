#pragma once
// The VesselGlyph region TFs a user has not chosen. VesselGlyph shows the vessel with one TF and
// its surroundings with another (thesis ch. 5); until the user sets them, both come from the main
// TF the user already tuned for this scan: the focus as it is, the context faded so that the
// vessel stands out in front of it while the surroundings still give orientation.
#include "core/transfer_function.h"

namespace angio {

// The focus follows the main TF as it is; the context's opacity is this fraction of the main TF's
// (through its opacity modulator, so the TF editor shows the main TF's points and the fade as a
// modulator the user can change).
inline constexpr double kFollowingContextOpacity = 0.2;

TransferFunction followingContextTf(const TransferFunction& main);

}  // namespace angio
