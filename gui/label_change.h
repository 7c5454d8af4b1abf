#pragma once
// A change of the voxels' labels (bone removal, a grown region, a label file) as one undoable
// step: the voxels it touches with their labels before and after, so undo and redo rewrite just
// those label bits (a removal touches a few percent of the voxels, not the volume).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/volume.h"

namespace angio {

struct LabelChange {
  std::string what;                 // for the Undo button's tooltip, e.g. "bone and table removal"
  std::vector<std::size_t> voxels;  // indices into Volume::voxels, ascending
  std::vector<std::uint8_t> before, after;

  bool empty() const { return voxels.empty(); }
};

using LabelCounts = std::array<std::uint64_t, kLabelCount>;

// The change that gives the volume `labels` (one per voxel, Volume::voxels' order).
LabelChange changeTo(const Volume& volume, const std::vector<std::uint8_t>& labels, std::string what);
// The change that gives `voxels` the label `label` (those that have it already are left out).
LabelChange changeOf(const Volume& volume, const std::vector<std::size_t>& voxels, int label,
                     std::string what);

// Writes the change's labels (after; with `undo` before) into the volume's label bits and
// updates `counts` (voxels per label) to match.
void apply(const LabelChange& change, bool undo, Volume& volume, LabelCounts& counts);

LabelCounts countLabels(const Volume& volume);

}  // namespace angio
