#pragma once
// Re-encoding a DICOM slice in place with one of GDCM's codecs (encapsulated pixel data), for the
// readers' tests of compressed series: what a PACS sends is often JPEG or JPEG 2000.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <gdcmImageChangeTransferSyntax.h>
#include <gdcmImageReader.h>
#include <gdcmImageWriter.h>

#include "tests/support/dicom_tag_patch.h"

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

// Puts two stray bytes before the JPEG frame header (SOF3) of a JPEG lossless slice and grows its
// fragment to match: libjpeg warns ("Corrupt JPEG data"), and GDCM's codec asserts on the warning.
inline void strayBytesBeforeJpegFrameHeader(const std::filesystem::path& file) {
  std::string bytes = fileBytes(file);
  const std::size_t frameHeader = bytes.find("\xff\xc3");
  const std::size_t fragment = bytes.rfind(std::string("\xfe\xff\x00\xe0", 4), frameHeader);
  if (frameHeader == std::string::npos || fragment == std::string::npos)
    throw std::runtime_error(file.string() + " has no JPEG lossless fragment");
  bytes.insert(frameHeader, "\x12\x34", 2);
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + fragment + 4, 4);
  length += 2;
  std::memcpy(bytes.data() + fragment + 4, &length, 4);
  overwrite(file, bytes);
}

}  // namespace angio::test_support
