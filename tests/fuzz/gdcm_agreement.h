#pragma once
// The differential half of the dicom_slice fuzz target: a file the element walk accepts
// (io/dicom_file_walk.h) must read the same in GDCM, the parser behind ITK's DICOM reader, read as
// the app reads a slice in its own process (up to the pixel data, io/dicom_slice_check.h; pixel
// data are decoded in a child process): the same SeriesInstanceUID at the top level, what a
// folder's slices are grouped by. Where they differ the walk stepped through other elements than
// GDCM does, so its length checks guarded other lengths than GDCM then trusts. A disagreement is a
// finding: it aborts with both readings.
#include <gdcmReader.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "io/dicom_file_walk.h"
#include "io/input_error.h"
#include "io/shown_text.h"

namespace angio::fuzz {

// GDCM's top-level SeriesInstanceUID as the walk keeps it: cut at 64 bytes (a UID's most), its
// trailing NULs and spaces removed.
inline std::string gdcmSeriesUid(const gdcm::DataSet& set) {
  const gdcm::Tag series(0x0020, 0x000e);
  if (!set.FindDataElement(series)) return "";
  const gdcm::ByteValue* value = set.GetDataElement(series).GetByteValue();
  if (!value || !value->GetPointer()) return "";
  std::string text(value->GetPointer(), std::min<std::size_t>(value->GetLength(), 64));
  while (!text.empty() && (text.back() == '\0' || text.back() == ' ')) text.pop_back();
  return text;
}

inline void requireGdcmAgrees(const std::filesystem::path& file) {
  std::optional<DicomFileFacts> facts;
  try {
    facts = walkDicomFile(file, file);
  } catch (const InputError&) {
    return;  // refused before GDCM would read it
  }
  // Not DICOM, or refused by what it is before GDCM reads it.
  if (!facts || !facts->imageProblem.empty()) return;
  const gdcm::Tag pixelData(0x7fe0, 0x0010);
  gdcm::Reader reader;
  reader.SetFileName(file.c_str());
  if (!reader.ReadUpToTag(pixelData, {pixelData})) return;  // GDCM refuses it too
  const std::string ours = quotedText(facts->seriesUid);
  const std::string gdcm = quotedText(gdcmSeriesUid(reader.GetFile().GetDataSet()));
  if (ours == gdcm) return;
  std::fprintf(stderr, "GDCM reads the series UID otherwise:\n  ours: %s\n  GDCM: %s\n", ours.c_str(),
               gdcm.c_str());
  std::abort();
}

}  // namespace angio::fuzz
