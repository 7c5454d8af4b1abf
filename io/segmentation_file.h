#pragma once
// 3D Slicer segmentation files (.seg.nrrd): a NRRD label map with the segments' names, colors and
// label values as key/value header fields, as Slicer's vtkMRMLSegmentationStorageNode writes and
// reads them (Slicer 4.11 and 5.x). A segment's label value is our voxel label (1..15; rendering-
// model.md "Labels"). Reading a .seg.nrrd's voxels is ReadOptions::labelPath's job (volume_reader.h);
// this file writes them and reads what the header says about the segments. Errors are InputErrors
// naming the file.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/volume.h"
#include "core/voxel.h"

namespace angio {

struct SegmentInfo {
  int label = 0;  // 1..15, the voxels' label and the segment's LabelValue in the file
  std::string name;
  glm::vec3 color{0.f};  // r, g, b in 0..1

  friend bool operator==(const SegmentInfo&, const SegmentInfo&) = default;
};

// What a segmentation file's header says about its segments (its voxels are read as labels).
struct SegmentationInfo {
  std::vector<SegmentInfo> segments;  // in file order (Segment0, Segment1, ...)
  int layers = 1;                     // more than one when segments overlap (a 4-D file)

  friend bool operator==(const SegmentationInfo&, const SegmentationInfo&) = default;
};

// Writes the label bits of `volume` as a single-layer uint8 label map on the volume's grid (as
// writeLabelVolume does), with the Segmentation_* and SegmentN_* fields Slicer writes for
// `segments`, each with its bounding box (an empty one for a segment with no voxels). A label
// that voxels carry but no segment names gets a segment "label N" (gray), so nothing is lost.
// The file must be .nrrd (normally .seg.nrrd) or .nhdr. Atomic. Throws InputError naming `file`
// (a label outside 1..15 or given twice, an unwritable file).
void writeSegmentation(const std::filesystem::path& file, const Volume& volume,
                       const std::vector<SegmentInfo>& segments);

// The segments of a Slicer segmentation file, or nothing for a file that is not one (another
// format, or a NRRD without Segmentation_/SegmentN_ fields: a plain label volume). Throws
// InputError for a file that cannot be read or whose segment fields are inconsistent (a segment
// without ID or LabelValue, a LabelValue outside 1..15 or used twice in a layer, a Layer outside
// the file's layers).
std::optional<SegmentationInfo> readSegmentationInfo(const std::filesystem::path& file);

// For reading a segmentation's single layer as labels: which stored values 0..15 are labels (the
// background 0 and the segments' label values). Throws InputError naming `file` for a
// segmentation with overlapping segments (more than one layer).
std::array<bool, kMaxLabel + 1> segmentLabelValues(const std::filesystem::path& file,
                                                   const SegmentationInfo& segmentation);

}  // namespace angio
