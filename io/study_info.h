#pragma once
// Who and what a dataset is (the banner a reading workstation shows over the image): patient name
// and ID, study date, series description and modality from a DICOM series' tags. Empty for
// formats without them (NRRD, MetaImage, NIfTI) and for anonymised series.
#include <string>

namespace angio {

struct StudyInfo {
  std::string patientName;        // readable: "DOE, JANE" from the DICOM "DOE^JANE"
  std::string patientId;          // (0010,0020)
  std::string studyDate;          // readable: "2024-03-01" from "20240301"
  std::string seriesDescription;  // (0008,103E)
  std::string modality;           // (0008,0060), e.g. "CT"

  bool empty() const { return *this == StudyInfo{}; }
  friend bool operator==(const StudyInfo&, const StudyInfo&) = default;
};

// A DICOM person name (PN: family^given^middle^prefix^suffix, "=" between the alphabetic,
// ideographic and phonetic forms) as "FAMILY, GIVEN MIDDLE": the alphabetic form only, empty
// components left out, padding trimmed.
std::string readablePersonName(const std::string& dicomName);

// A DICOM date (DA: YYYYMMDD) as YYYY-MM-DD; anything else trimmed and as it is.
std::string readableDate(const std::string& dicomDate);

// The value with DICOM's padding (trailing spaces and NULs, leading spaces) removed.
std::string trimmedDicomValue(const std::string& value);

}  // namespace angio
