#pragma once
// Paths of one vessel tree in vmtk's layout: each runs root to leaf and repeats its trunk. Traced
// separately (two clicks each, or branch by branch downstream), two paths through one trunk lie
// within a fraction of a voxel of each other there but are not the same points; this makes them
// the same, so the trunk is recognised (sharedPrefixLength) and rendered once.
#include <vector>

#include "vessel/centerline.h"

namespace angio {

// Where `path` starts along one of `earlier` (within a quarter of its radius, at least 0.5 mm, for
// the longest stretch), its points up to shortly before they part (two radii, before the
// bifurcation pulls the sections apart) are replaced by that path's. Unchanged when it starts
// along none of them for at least two radii.
void shareTrunk(CenterlinePath& path, const std::vector<CenterlinePath>& earlier);

}  // namespace angio
