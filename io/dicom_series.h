#pragma once
// Reading a folder of DICOM slices (GDCM through ITK) into a voxel stack, not yet reoriented.
// The series with the most slices is chosen (the others are named in a warning); slices are
// ordered by position along the slice normal (ImagePositionPatient), never by file name or
// InstanceNumber; rescale slope/intercept is applied; gaps, duplicate positions and mixed
// orientations or sizes are InputErrors naming the folder.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/voxel.h"
#include "io/study_info.h"
#include "io/volume_reader.h"
#include "io/volume_reorientation.h"

namespace angio {

// A series chosen and checked from its slices' headers, before any pixel is read.
struct DicomSeries {
  VolumeGeometry geometry;         // axes: row direction, column direction, slice normal
  std::vector<std::string> files;  // the slices in position order
  std::string description;         // "DICOM series <uid> (<n> slices)"
  StudyInfo study;                 // from the first slice's tags
  bool compressed = false;         // a slice has encapsulated pixel data: decoded in a child process
};

// Chooses the series and reads every slice's header: orientation, size, positions (no gaps, no
// shear) are checked here, so a series that cannot be stacked is refused before its pixels.
DicomSeries scanDicomSeries(const std::filesystem::path& folder, const ReadOptions& options);

// Reads the slices' pixels in position order, each as encoded voxels (i fastest, columns x rows),
// handing slice k to slice(k, voxels) (valid during the call): one slice in memory at a time.
// Compressed slices are decoded in a child process (io/slices_in_child.h).
// Returns how many pixel values were NaN/Inf (float pixel data; stored as -1024 HU).
std::size_t readDicomSlices(const std::filesystem::path& folder, const DicomSeries& series,
                            const std::function<void(int, const Voxel*)>& slice,
                            const ReadOptions& options);

// Positions (mm, along the normal) of the slices missing from a sorted stack; empty if none.
// Throws std::invalid_argument describing the problem if the positions are not a uniform grid
// with some slices missing (duplicates, or steps that are not a multiple of the common step).
// Exposed for tests.
std::vector<double> missingSlicePositions(const std::vector<double>& sortedPositions);

}  // namespace angio
