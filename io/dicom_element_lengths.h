#pragma once
// Walking a DICOM file's element headers ourselves before GDCM reads it: GDCM allocates (and
// zeroes) as many bytes as an element's length field says before it finds the file is shorter,
// so a damaged or hostile length makes it take gigabytes for a file of kilobytes.
#include <filesystem>

namespace angio {

// Throws InputError naming `reported` (the folder or file the user gave) and the file when an
// element's defined length runs past the end of the file, or its header is not DICOM. Returns
// false, checking nothing, for a file that does not start like DICOM (no "DICM" at byte 128, no
// group 0002 or 0008 tag at byte 0), which GDCM does not take for a slice either.
bool checkDicomElementLengths(const std::filesystem::path& reported, const std::filesystem::path& file);

}  // namespace angio
