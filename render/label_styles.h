#pragma once
// Editing the label styles of a recipe's TF (rendering model, "Labels"): labels by name or number,
// a label's mode, and the "show removed" view in which hidden labels render translucent so the
// user sees what was cut. Shared by the command line and the workstation.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/labels.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "io/segmentation_file.h"

namespace angio {

// "bone", "table", "label N" for the user's labels.
std::string defaultLabelName(int label);
glm::vec3 defaultLabelColor(int label);

// The label a user means: a number 1..15, a style's name, or a default name (case-insensitive).
std::optional<int> findLabel(const std::vector<LabelStyle>& styles, const std::string& nameOrNumber);

// The style of `label`, added with its default name and color where the list has none.
LabelStyle& styleOf(std::vector<LabelStyle>& styles, int label);

// Hides each label `names` names (as findLabel reads them), adding a style where there is none.
// Throws std::invalid_argument ("--hide NAME: no such label ...") for one that names no label.
void hideLabels(std::vector<LabelStyle>& styles, const std::vector<std::string>& names);

// The Slicer segments of the labels a volume has (`voxels` per label), named and colored by
// their styles (or the defaults).
std::vector<SegmentInfo> segmentsOf(const std::vector<LabelStyle>& styles,
                                    const std::array<std::uint64_t, kLabelCount>& voxels);

// Writes the volume's labels: a .seg.nrrd as a Slicer segmentation with those segments, any other
// name as a plain label volume (io/label_volume_file.h). Throws InputError naming the file.
void writeLabelFile(const std::filesystem::path& file, const Volume& volume,
                    const std::vector<LabelStyle>& styles,
                    const std::array<std::uint64_t, kLabelCount>& voxels);

// Hidden labels as translucent ones: each gets an own TF in its color, faint above -500 HU, so
// the removed structures stay in place as a ghost around what remains.
std::vector<LabelStyle> withRemovedShown(std::vector<LabelStyle> styles);

}  // namespace angio
