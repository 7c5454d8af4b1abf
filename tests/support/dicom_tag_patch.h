#pragma once
// Rewriting one tag's value in the bytes of a DICOM slice written by test_support::writeDicomSlice
// (ITK writes implicit VR little endian: tag, 4-byte length, value), to make slices a reader must
// refuse.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/file_bytes.h"

namespace angio::test_support {

namespace fs = std::filesystem;

inline std::string littleEndian(std::uint32_t value, int bytes) {
  std::string out;
  for (int n = 0; n < bytes; ++n) out += char((value >> (8 * n)) & 0xff);
  return out;
}

// Replaces the value of tag (group, element) in an implicit-VR little-endian slice.
inline void setDicomTag(const fs::path& slice, std::uint16_t group, std::uint16_t element,
                        const std::string& value) {
  std::string bytes = fileBytes(slice);
  const std::string tag = littleEndian(group, 2) + littleEndian(element, 2);
  // The data set starts after the file meta group (0002); search from the first (0008) tag.
  const std::size_t dataSet = bytes.find(littleEndian(0x0008, 2), 132 + 12);
  const std::size_t at = bytes.find(tag, dataSet);
  ASSERT_NE(at, std::string::npos) << "no tag " << std::hex << group << "," << element;
  const std::uint32_t length = std::uint8_t(bytes[at + 4]) | std::uint8_t(bytes[at + 5]) << 8 |
                               std::uint8_t(bytes[at + 6]) << 16 |
                               std::uint32_t(std::uint8_t(bytes[at + 7])) << 24;
  bytes.replace(at + 4, 4 + length, littleEndian(std::uint32_t(value.size()), 4) + value);
  overwrite(slice, bytes);
}

inline std::string unsignedShort(int value) { return littleEndian(std::uint32_t(value), 2); }

// Cuts the last `bytes` bytes off `file` (a slice whose pixel data is truncated).
inline void truncateBy(const fs::path& file, std::size_t bytes) {
  const std::string all = fileBytes(file);
  overwrite(file, all.substr(0, all.size() - bytes));
}

}  // namespace angio::test_support
