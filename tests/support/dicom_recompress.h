#pragma once
// Re-encoding a DICOM slice in place with one of GDCM's codecs (encapsulated pixel data), for the
// readers' tests of compressed series: what a PACS sends is often JPEG or JPEG 2000.
#include <filesystem>
#include <stdexcept>

#include <gdcmImageChangeTransferSyntax.h>
#include <gdcmImageReader.h>
#include <gdcmImageWriter.h>

namespace angio::test_support {

inline void recompressDicomSlice(const std::filesystem::path& file,
                                 gdcm::TransferSyntax::TSType syntax) {
  gdcm::ImageReader reader;
  reader.SetFileName(file.c_str());
  if (!reader.Read()) throw std::runtime_error("GDCM cannot read " + file.string());
  gdcm::ImageChangeTransferSyntax change;
  change.SetTransferSyntax(syntax);
  change.SetInput(reader.GetImage());
  if (!change.Change()) throw std::runtime_error("GDCM cannot encode " + file.string());
  gdcm::ImageWriter writer;
  writer.SetFile(reader.GetFile());
  writer.SetImage(change.GetOutput());
  writer.SetFileName(file.c_str());
  if (!writer.Write()) throw std::runtime_error("GDCM cannot write " + file.string());
}

}  // namespace angio::test_support
