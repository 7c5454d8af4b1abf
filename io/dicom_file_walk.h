#pragma once
// Walking a DICOM file's element headers ourselves before GDCM reads it. GDCM trusts what it reads:
// it allocates (and zeroes) as many bytes as an element's length field says before it finds the
// file is shorter, and it asserts (aborting the process) on a file that ends inside its file meta
// group, an element header or an item of undefined length. The walk refuses those files with a message, and collects what
// a folder of slices is grouped by, so GDCM never scans a folder itself.
#include <filesystem>
#include <optional>
#include <string>

namespace angio {

// What the walk saw at the top level of the data set (not inside sequences, where referenced
// series and images have tags of their own).
struct DicomFileFacts {
  std::string seriesUid;      // SeriesInstanceUID (0020,000E), trailing padding removed
  bool hasPixelData = false;  // (7FE0,0010): the file is an image, not a report or a DICOMDIR
  // Why GDCM's image reader must not read it though it is well formed (a multi-frame SOP class,
  // NumberOfFrames > 1, waveforms, ...: io/dicom_element_check.h); empty if nothing was found.
  std::string imageProblem;

  bool operator==(const DicomFileFacts&) const = default;
};

// Throws InputError naming `reported` (the folder or file the user gave) and the file when an
// element's defined length runs past the end of the file, its header is not DICOM, or the file ends
// inside its file meta group or an element header. Returns nullopt, reading nothing into GDCM, for a
// file that does not start like DICOM (no "DICM" at byte 128, no group 0002 or 0008 tag at byte 0).
std::optional<DicomFileFacts> walkDicomFile(const std::filesystem::path& reported,
                                            const std::filesystem::path& file);

}  // namespace angio
