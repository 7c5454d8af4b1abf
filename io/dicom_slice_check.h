#pragma once
// Checking a DICOM slice's image tags ourselves before GDCM decodes it. Debian builds GDCM and ITK
// with assertions on, and they assert (stopping the process) when a slice's Rows, Columns,
// SamplesPerPixel or BitsAllocated contradict its pixel data; other bad values (a zero or NaN
// PixelSpacing, an all-zero ImageOrientationPatient, a NaN RescaleSlope) they replace with
// defaults, which would load a wrong volume silently. So the tags are read here without the pixel
// data and every such slice is refused with one line naming it and the tag.
#include <filesystem>

#include <glm/glm.hpp>

#include "io/study_info.h"

namespace angio {

// What a checked slice says of itself (the values the checks read).
struct DicomSliceTags {
  int rows = 0, columns = 0;
  int bitsAllocated = 0;
  glm::dvec2 pixelSpacing{0.0};      // mm between columns, between rows
  glm::dvec3 position{0.0};          // ImagePositionPatient (mm, LPS)
  glm::dvec3 row{0.0}, column{0.0};  // ImageOrientationPatient: direction cosines
  bool encapsulated = false;         // compressed pixel data, whose length cannot be checked up front
  StudyInfo study;                   // patient and study tags (all slices of a series share them)
};

// The slice's tags, or an InputError naming `reported` (the folder or file the user gave) and the
// slice. `requirePlacement`: a slice of a series must say where it lies (ImagePositionPatient,
// ImageOrientationPatient, PixelSpacing); a lone file may leave them out.
DicomSliceTags checkDicomSlice(const std::filesystem::path& reported, const std::filesystem::path& slice,
                               bool requirePlacement);

}  // namespace angio
