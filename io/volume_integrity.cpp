#include "io/volume_integrity.h"

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
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

// Voxel data as text: every value takes a digit and a separator at least, the last one's separator
// only where the reader needs it (MetaIO fails on a last value that ends the file; teem does not).
struct TextDataBound {
  std::uint64_t bytes = 0;
  std::string fewest;  // "bytes of voxel data as text cannot hold the 8 values its header promises ..."
};

TextDataBound textDataBound(const StoredDataSize& size, bool lastNeedsSeparator) {
  const std::uint64_t values = size.voxelBytes / std::max(1u, size.componentBytes);
  return {values == 0 ? 0 : 2 * values - (lastNeedsSeparator ? 0 : 1),
          "bytes of voxel data as text cannot hold the " + std::to_string(values) +
              " values its header promises (2 bytes each at least)"};
}

// ---- MetaImage: LOCAL data follow the header; a data file may skip HeaderSize bytes.

// The bytes of voxel data a MetaImage header promises; for text and for compressed data without a
// size only the fewest that could hold the voxels, with what the message says of them.
struct PromisedData {
  std::uint64_t bytes = 0;
  std::string fewest;  // "bytes of compressed voxel data cannot hold the 524288 bytes ...", or ""
};

PromisedData promisedMetaImageData(const std::filesystem::path& file, const MetaImageHeader& header,
                                   const StoredDataSize& size) {
  if (!header.flag("BinaryData", true)) {
    TextDataBound text = textDataBound(size, true);
    return {text.bytes, std::move(text.fewest)};
  }
  if (!header.flag("CompressedData")) return {size.voxelBytes, ""};
  // MetaIO allocates as many bytes as it reads (a negative size wraps around to nearly 2^64).
  const std::optional<double> compressedSize = header.number("CompressedDataSize");
  if (compressedSize && !(*compressedSize >= 0 && *compressedSize < 9e18))
    throw InputError(file, "has an impossible CompressedDataSize (" +
                               shownText(header.field("CompressedDataSize")) + ")");
  if (compressedSize) return {std::uint64_t(*compressedSize), ""};
  // Without a size: zlib's deflate packs at most 1032 bytes into one.
  return {(size.voxelBytes + kMaxDeflateRatio - 1) / kMaxDeflateRatio,
          "bytes of compressed voxel data cannot hold the " + std::to_string(size.voxelBytes) +
              " bytes its header promises (zlib compresses at most " + std::to_string(kMaxDeflateRatio) +
              ":1)"};
}

// The bytes of voxel data the file holds, or nothing where that is not known (lists of files).
std::optional<std::uint64_t> metaImageDataBytes(const std::filesystem::path& file,
                                                const MetaImageHeader& header) {
  const std::string dataFile = header.field("ElementDataFile");
  if (dataFile == "LOCAL") {
    if (!header.dataStart) return 0;  // the header ends the file
    const std::uint64_t size = std::filesystem::file_size(file);
    return size > *header.dataStart ? size - *header.dataStart : 0;
  }
  // LIST or a printf pattern name several files; skip those.
  if (dataFile == "LIST" || dataFile.find_first_of("% ") != std::string::npos) return std::nullopt;
  std::error_code error;
  const std::uint64_t size = std::filesystem::file_size(file.parent_path() / dataFile, error);
  if (error)
    throw InputError(file,
                     "its data file " + quotedText(dataFile) + " cannot be read: " + error.message());
  long headerBytes = 0;
  try {
    headerBytes = std::stol(header.field("HeaderSize"));
  } catch (const std::exception&) {
  }
  return headerBytes > 0 ? (size > std::uint64_t(headerBytes) ? size - headerBytes : 0) : size;
}

void requireCompleteMetaImage(const std::filesystem::path& file, const StoredDataSize& size) {
  const MetaImageHeader header = readMetaImageHeader(file);
  if (header.field("ElementDataFile").empty()) return;
  const PromisedData promised = promisedMetaImageData(file, header, size);
  const std::optional<std::uint64_t> found = metaImageDataBytes(file, header);
  if (!found || *found >= promised.bytes) return;
  if (!promised.fewest.empty())
    throw InputError(file, "is truncated: its " + std::to_string(*found) + " " + promised.fewest);
  truncated(file, promised.bytes, *found);
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

void requireCompleteNrrdText(const std::filesystem::path& file, const NrrdDataStart& start,
                             const StoredDataSize& size) {
  const bool text = start.encoding == "ascii" || start.encoding == "text" || start.encoding == "txt";
  if (!text && start.encoding != "hex") return;
  std::error_code error;
  const std::uint64_t fileBytes = std::filesystem::file_size(start.dataFile, error);
  if (error) return;  // teem says it cannot open it
  const std::uint64_t found = fileBytes > start.fileOffset ? fileBytes - start.fileOffset : 0;
  const TextDataBound bound =
      text ? textDataBound(size, false)
           : TextDataBound{2 * size.voxelBytes, "bytes of voxel data as hex cannot hold the " +
                                                    std::to_string(size.voxelBytes) +
                                                    " bytes its header promises (2 digits each)"};
  if (found >= bound.bytes) return;
  std::string message = "is truncated: its " + std::to_string(found);
  message += " " + bound.fewest;
  throw InputError(file, message);
}

void requireCompleteData(const std::filesystem::path& file, VolumeFormat format,
                         const StoredDataSize& size) {
  if (format == VolumeFormat::metaImage) requireCompleteMetaImage(file, size);
  if (format == VolumeFormat::nifti) requireCompleteNifti(file);
}

}  // namespace angio
