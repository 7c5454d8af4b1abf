#pragma once
// Volume loading through ITK: DICOM series (directory), NIfTI, NRRD, MetaImage. Values are taken
// as HU (DICOM rescale applied), stored as the rendering model's 12-bit densities, and the volume is
// reoriented to the LPS-aligned frame (voxel axes along +L, +P, +S). Throws InputError with a
// one-line message naming the file and the problem.
#include <filesystem>
#include <exception>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/volume.h"
#include "io/study_info.h"

namespace angio {

struct ReadOptions {
  // Optional label volume on the same grid; its values (0..15) go into the 4 label bits. A 3D
  // Slicer segmentation (.seg.nrrd, one layer) gives its segments' label values (segmentation_file.h).
  std::filesystem::path labelPath;
  // Called with each warning (NaN replaced, oblique snapped, other DICOM series present, ...).
  std::function<void(const std::string&)> warn;
  // Called with load progress in [0, 1]; may be empty. It may throw LoadCancelled to stop the load.
  std::function<void(double)> progress;
};

// Thrown by a progress callback to stop a load (the user cancelled); readVolume passes it on as is.
struct LoadCancelled : std::exception {
  const char* what() const noexcept override { return "load cancelled"; }
};

struct LoadedVolume {
  Volume volume;
  std::string description;  // e.g. "DICOM series 1.2.3 (120 slices)", "MetaImage float32"
  StudyInfo study;          // DICOM series only
};

LoadedVolume readVolume(const std::filesystem::path& path, const ReadOptions& options = {});

// The labels of a label volume or Slicer segmentation on `volume`'s grid, one per voxel in the
// volume's order (after the same reorientation); as ReadOptions::labelPath reads them.
std::vector<std::uint8_t> readLabels(const std::filesystem::path& file, const Volume& volume,
                                     const ReadOptions& options = {});

}  // namespace angio
