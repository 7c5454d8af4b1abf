#include "io/volume_integrity.h"

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include <fstream>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "io/metaimage_header.h"
#include "io/nifti_header.h"
#include "io/shown_text.h"

namespace angio {

namespace {

[[noreturn]] void truncated(const std::filesystem::path& file, std::uint64_t expected,
                            std::uint64_t found) {
  throw InputError(file, "is truncated: its header promises " + std::to_string(expected) +
                             " bytes of voxel data, the file holds " + std::to_string(found));
}

constexpr std::uint64_t kMaxDeflateRatio = 1032;  // zlib's limit (zlib technical details)

// ---- MetaImage: LOCAL data follows the header; a data file may skip HeaderSize bytes.
void requireCompleteMetaImage(const std::filesystem::path& file, std::uint64_t voxelBytes) {
  const MetaImageHeader header = readMetaImageHeader(file);
  const auto field = [&](const char* key) { return header.field(key); };
  if (field("ElementDataFile").empty() || (!field("BinaryData").empty() && !header.flag("BinaryData")))
    return;
  const bool compressed = header.flag("CompressedData");
  std::uint64_t expected = voxelBytes;
  // Compressed without a size: zlib's deflate packs at most 1032 bytes into one, so fewer
  // compressed bytes than voxelBytes / 1032 cannot hold the voxels.
  bool leastCompressed = false;
  if (compressed) {
    // MetaIO allocates as many bytes as it reads (a negative size wraps around to nearly 2^64).
    const std::optional<double> size = header.number("CompressedDataSize");
    if (size && !(*size >= 0 && *size < 9e18))
      throw InputError(
          file, "has an impossible CompressedDataSize (" + shownText(field("CompressedDataSize")) + ")");
    leastCompressed = !size;
    expected = size ? std::uint64_t(*size) : (voxelBytes + kMaxDeflateRatio - 1) / kMaxDeflateRatio;
  }
  std::uint64_t found = 0;
  const std::string dataFile = field("ElementDataFile");
  if (dataFile == "LOCAL") {
    if (!header.dataStart) return;
    const std::uint64_t dataStart = *header.dataStart;
    const std::uint64_t size = std::filesystem::file_size(file);
    found = size > dataStart ? size - dataStart : 0;
  } else {
    // LIST or a printf pattern name several files; skip those.
    if (dataFile == "LIST" || dataFile.find_first_of("% ") != std::string::npos) return;
    const std::filesystem::path data = file.parent_path() / dataFile;
    std::error_code error;
    const std::uint64_t size = std::filesystem::file_size(data, error);
    if (error)
      throw InputError(file,
                       "its data file " + quotedText(dataFile) + " cannot be read: " + error.message());
    found = size;
    long headerBytes = 0;
    try {
      headerBytes = std::stol(field("HeaderSize"));
    } catch (const std::exception&) {
    }
    if (headerBytes > 0) found = found > std::uint64_t(headerBytes) ? found - headerBytes : 0;
  }
  if (found < expected && leastCompressed)
    throw InputError(file, "is truncated: its " + std::to_string(found) +
                               " bytes of compressed voxel data cannot hold the " +
                               std::to_string(voxelBytes) +
                               " bytes its header promises (zlib compresses at most " +
                               std::to_string(kMaxDeflateRatio) + ":1)");
  if (found < expected) truncated(file, expected, found);
}

// Uncompressed length of the gzip stream from byte `offset` of `file` to its end: the trailer's
// ISIZE (length mod 2^32) when it matches `expected`, else counted by decompressing (multi-member
// files, truncation, trailing bytes).
std::uint64_t gzipLength(const std::filesystem::path& file, std::uint64_t expected,
                         std::uint64_t offset = 0) {
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
  const int descriptor = ::open(file.c_str(), O_RDONLY);
  if (descriptor < 0) return 0;
  gzFile gz = ::lseek(descriptor, off_t(offset), SEEK_SET) == off_t(offset) ? gzdopen(descriptor, "rb")
                                                                            : nullptr;
  if (!gz) {
    ::close(descriptor);
    return 0;
  }
  gzbuffer(gz, 1 << 20);
  std::vector<char> chunk(1 << 20);
  std::uint64_t length = 0;
  int read = 0;
  while ((read = gzread(gz, chunk.data(), unsigned(chunk.size()))) > 0) length += std::uint64_t(read);
  gzclose(gz);
  return length;
}

// ---- NIfTI-1/-2: the header gives the data offset and size; .nii.gz is gzip-compressed.
void requireCompleteNifti(const std::filesystem::path& file) {
  const auto header = readNiftiHeader(file);
  if (!header) return;  // the reader reports the broken header itself
  const std::uint64_t expected = header->dataOffset + header->dataBytes;
  const std::uint64_t found =
      header->compressed ? gzipLength(file, expected) : std::filesystem::file_size(file);
  if (found < expected)
    truncated(file, header->dataBytes, found > header->dataOffset ? found - header->dataOffset : 0);
}

}  // namespace

void requireCompleteNrrdData(const std::filesystem::path& file, const VoxelDataLayout& layout,
                             std::uint64_t voxelBytes) {
  std::uint64_t found = 0;
  if (layout.encoding == VoxelEncoding::deflate) {
    found = gzipLength(layout.dataFile, voxelBytes, layout.fileOffset);
  } else {
    std::error_code error;
    const std::uint64_t size = std::filesystem::file_size(layout.dataFile, error);
    if (error)
      throw InputError(file, "its data file " + quotedText(layout.dataFile.filename().string()) +
                                 " cannot be read: " + error.message());
    found = size > layout.fileOffset ? size - layout.fileOffset : 0;
  }
  if (found < voxelBytes) truncated(file, voxelBytes, found);
}

void requireCompleteData(const std::filesystem::path& file, VolumeFormat format,
                         std::uint64_t voxelBytes) {
  if (format == VolumeFormat::metaImage) requireCompleteMetaImage(file, voxelBytes);
  if (format == VolumeFormat::nifti) requireCompleteNifti(file);
}

}  // namespace angio
