#pragma once
// Reading a folder of DICOM slices (GDCM through ITK) into a voxel stack, not yet reoriented.
// The series with the most slices is chosen (the others are named in a warning); slices are
// ordered by position along the slice normal (ImagePositionPatient), never by file name or
// InstanceNumber; rescale slope/intercept is applied; gaps, duplicate positions and mixed
// orientations or sizes are InputErrors naming the folder.
#include <filesystem>
#include <string>
#include <vector>

#include "core/voxel.h"
#include "io/study_info.h"
#include "io/volume_reader.h"
#include "io/volume_reorientation.h"

namespace angio {

struct DicomStack {
  VolumeGeometry geometry;    // axes: row direction, column direction, slice normal
  std::vector<Voxel> voxels;  // encoded densities, i fastest, slices in position order
  std::string description;    // "DICOM series <uid> (<n> slices)"
  std::size_t nonFinite = 0;  // NaN/Inf pixels (float pixel data), stored as -1024 HU
  StudyInfo study;            // from the first slice's tags
};

// `extraBytesPerVoxel`: what the caller will allocate on top (for the memory check up front).
DicomStack readDicomSeries(const std::filesystem::path& folder, const ReadOptions& options,
                           double extraBytesPerVoxel);

// Positions (mm, along the normal) of the slices missing from a sorted stack; empty if none.
// Throws std::invalid_argument describing the problem if the positions are not a uniform grid
// with some slices missing (duplicates, or steps that are not a multiple of the common step).
// Exposed for tests.
std::vector<double> missingSlicePositions(const std::vector<double>& sortedPositions);

}  // namespace angio
