#pragma once
// A file's bytes read or written whole, for tests that make, damage or compare files byte by byte.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace angio::test_support {

// The bytes of `file` ("" if it cannot be read).
inline std::string fileBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Replaces the bytes of `file` (creates it).
inline void overwrite(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace angio::test_support
