#include "io/volume_integrity.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "io/input_error.h"

namespace angio {

namespace {

[[noreturn]] void truncated(const std::filesystem::path& file, std::uint64_t expected,
                            std::uint64_t found) {
  throw InputError(file, "is truncated: its header promises " + std::to_string(expected) +
                             " bytes of voxel data, the file holds " + std::to_string(found));
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  const auto last = text.find_last_not_of(" \t\r");
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

// ---- MetaImage: a text header of "Key = Value" lines ending with ElementDataFile; LOCAL data
// follows that line directly.
void requireCompleteMetaImage(const std::filesystem::path& file, std::uint64_t voxelBytes) {
  std::ifstream in(file, std::ios::binary);
  std::map<std::string, std::string> fields;
  std::string line;
  for (int lines = 0; lines < 4096 && std::getline(in, line); ++lines) {
    const auto equals = line.find('=');
    if (equals == std::string::npos) continue;
    const std::string key = trimmed(line.substr(0, equals));
    fields[key] = trimmed(line.substr(equals + 1));
    if (key == "ElementDataFile") break;
  }
  const auto field = [&](const char* key) { return fields.count(key) ? fields[key] : std::string(); };
  if (field("ElementDataFile").empty() || field("BinaryData") == "False") return;
  const bool compressed = field("CompressedData") == "True";
  std::uint64_t expected = voxelBytes;
  if (compressed) {
    try {
      expected = std::stoull(field("CompressedDataSize"));
    } catch (const std::exception&) {
      return;  // compressed without a size: nothing to compare with
    }
  }
  std::uint64_t found = 0;
  const std::string dataFile = field("ElementDataFile");
  if (dataFile == "LOCAL") {
    if (!in) return;
    const std::uint64_t dataStart = std::uint64_t(in.tellg());
    const std::uint64_t size = std::filesystem::file_size(file);
    found = size > dataStart ? size - dataStart : 0;
  } else {
    // LIST or a printf pattern name several files; skip those.
    if (dataFile == "LIST" || dataFile.find_first_of("% ") != std::string::npos) return;
    const std::filesystem::path data = file.parent_path() / dataFile;
    std::error_code error;
    const std::uint64_t size = std::filesystem::file_size(data, error);
    if (error)
      throw InputError(file, "its data file " + dataFile + " cannot be read: " + error.message());
    found = size;
    long headerBytes = 0;
    try {
      headerBytes = std::stol(field("HeaderSize"));
    } catch (const std::exception&) {
    }
    if (headerBytes > 0) found = found > std::uint64_t(headerBytes) ? found - headerBytes : 0;
  }
  if (found < expected) truncated(file, expected, found);
}

// ---- NIfTI-1/-2: a binary header giving the data offset, dims and bits per voxel; .nii.gz is the
// same gzip-compressed. zlib's gz* functions read plain files too.
template <class T>
T fieldAt(const std::array<unsigned char, 540>& header, std::size_t offset, bool swap) {
  std::array<unsigned char, sizeof(T)> bytes;
  std::memcpy(bytes.data(), header.data() + offset, sizeof(T));
  if (swap) std::reverse(bytes.begin(), bytes.end());
  T value;
  std::memcpy(&value, bytes.data(), sizeof(T));
  return value;
}

struct NiftiLayout {
  std::uint64_t dataOffset = 0;
  std::uint64_t dataBytes = 0;
};

std::optional<NiftiLayout> niftiLayout(const std::array<unsigned char, 540>& header, int headerBytes) {
  for (bool swap : {false, true}) {
    const std::int32_t size = fieldAt<std::int32_t>(header, 0, swap);
    const bool nifti2 = size == 540;
    if (size != 348 && !nifti2) continue;
    if (nifti2 && headerBytes < 540) return std::nullopt;
    const int rank =
        nifti2 ? int(fieldAt<std::int64_t>(header, 16, swap)) : fieldAt<std::int16_t>(header, 40, swap);
    const int bitsPerVoxel = fieldAt<std::int16_t>(header, nifti2 ? 14 : 72, swap);
    if (rank < 1 || rank > 7 || bitsPerVoxel <= 0) return std::nullopt;
    double voxels = 1.0;
    for (int d = 1; d <= rank; ++d) {
      const double n = nifti2 ? double(fieldAt<std::int64_t>(header, 16 + 8 * d, swap))
                              : double(fieldAt<std::int16_t>(header, 40 + 2 * d, swap));
      voxels *= std::max(n, 1.0);
    }
    const double offset = nifti2 ? double(fieldAt<std::int64_t>(header, 168, swap))
                                 : double(fieldAt<float>(header, 108, swap));
    if (!(offset >= 0.0) || voxels * bitsPerVoxel / 8 > 1e18) return std::nullopt;
    return NiftiLayout{std::uint64_t(offset), std::uint64_t(voxels * bitsPerVoxel / 8)};
  }
  return std::nullopt;
}

// Uncompressed length of a gzip file: the trailer's ISIZE (length mod 2^32) when it matches
// `expected`, else counted by decompressing (multi-member files, truncation, trailing bytes).
std::uint64_t gzipLength(const std::filesystem::path& file, std::uint64_t expected) {
  {
    std::ifstream in(file, std::ios::binary | std::ios::ate);
    if (in && in.tellg() >= 4) {
      in.seekg(-4, std::ios::end);
      unsigned char trailer[4];
      in.read(reinterpret_cast<char*>(trailer), 4);
      const std::uint32_t length =
          trailer[0] | trailer[1] << 8 | trailer[2] << 16 | std::uint32_t(trailer[3]) << 24;
      if (in && length == std::uint32_t(expected)) return expected;
    }
  }
  gzFile gz = gzopen(file.c_str(), "rb");
  if (!gz) return 0;
  gzbuffer(gz, 1 << 20);
  std::vector<char> chunk(1 << 20);
  std::uint64_t length = 0;
  int read = 0;
  while ((read = gzread(gz, chunk.data(), unsigned(chunk.size()))) > 0) length += std::uint64_t(read);
  gzclose(gz);
  return length;
}

void requireCompleteNifti(const std::filesystem::path& file) {
  gzFile gz = gzopen(file.c_str(), "rb");
  if (!gz) return;
  std::array<unsigned char, 540> header{};
  const int headerBytes = gzread(gz, header.data(), unsigned(header.size()));
  const bool compressed = gzdirect(gz) == 0;
  gzclose(gz);
  if (headerBytes < 348) return;  // the reader reports the broken header itself
  const auto layout = niftiLayout(header, headerBytes);
  if (!layout) return;
  const std::uint64_t expected = layout->dataOffset + layout->dataBytes;
  const std::uint64_t found = compressed ? gzipLength(file, expected) : std::filesystem::file_size(file);
  if (found < expected)
    truncated(file, layout->dataBytes, found > layout->dataOffset ? found - layout->dataOffset : 0);
}

}  // namespace

void requireCompleteData(const std::filesystem::path& file, VolumeFormat format,
                         std::uint64_t voxelBytes) {
  if (format == VolumeFormat::metaImage) requireCompleteMetaImage(file, voxelBytes);
  if (format == VolumeFormat::nifti) requireCompleteNifti(file);
}

}  // namespace angio
