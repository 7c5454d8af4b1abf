#include "io/nifti_header.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace angio {

namespace {

using HeaderBytes = std::array<unsigned char, 540>;

template <class T>
T fieldAt(const HeaderBytes& header, std::size_t offset, bool swap) {
  std::array<unsigned char, sizeof(T)> bytes;
  std::memcpy(bytes.data(), header.data() + offset, sizeof(T));
  if (swap) std::reverse(bytes.begin(), bytes.end());
  T value;
  std::memcpy(&value, bytes.data(), sizeof(T));
  return value;
}

// NIfTI-1 stores floats and shorts, NIfTI-2 doubles and ints, at their own offsets.
void readPlacement(const HeaderBytes& header, bool swap, NiftiHeader& parsed) {
  const bool n2 = parsed.nifti2;
  const auto real = [&](std::size_t offset1, std::size_t offset2, int index) {
    return n2 ? fieldAt<double>(header, offset2 + 8 * index, swap)
              : double(fieldAt<float>(header, offset1 + 4 * index, swap));
  };
  for (int axis = 0; axis < 3; ++axis) parsed.pixdim[axis] = real(76, 104, axis + 1);
  parsed.qformCode =
      n2 ? fieldAt<std::int32_t>(header, 344, swap) : fieldAt<std::int16_t>(header, 252, swap);
  parsed.sformCode =
      n2 ? fieldAt<std::int32_t>(header, 348, swap) : fieldAt<std::int16_t>(header, 254, swap);
  for (int n = 0; n < 6; ++n) parsed.qform[n] = real(256, 352, n);
  for (int n = 0; n < 12; ++n) parsed.sform[n] = real(280, 400, n);
}

std::optional<NiftiHeader> parsed(const HeaderBytes& header, int headerBytes, bool swap) {
  const std::int32_t size = fieldAt<std::int32_t>(header, 0, swap);
  NiftiHeader parsed;
  parsed.nifti2 = size == 540;
  parsed.swapped = swap;
  if (size != 348 && !parsed.nifti2) return std::nullopt;
  if (parsed.nifti2 && headerBytes < 540) return std::nullopt;
  const bool n2 = parsed.nifti2;
  const int rank =
      n2 ? int(fieldAt<std::int64_t>(header, 16, swap)) : fieldAt<std::int16_t>(header, 40, swap);
  const int bitsPerVoxel = fieldAt<std::int16_t>(header, n2 ? 14 : 72, swap);
  if (rank < 1 || rank > 7 || bitsPerVoxel <= 0) return std::nullopt;
  double voxels = 1.0;
  for (int d = 1; d <= rank; ++d) {
    const double n = n2 ? double(fieldAt<std::int64_t>(header, 16 + 8 * d, swap))
                        : double(fieldAt<std::int16_t>(header, 40 + 2 * d, swap));
    voxels *= std::max(n, 1.0);
  }
  const double offset =
      n2 ? double(fieldAt<std::int64_t>(header, 168, swap)) : double(fieldAt<float>(header, 108, swap));
  // Both become 64-bit integers: beyond 1e18 (no file is that large) the conversion is undefined.
  if (!(offset >= 0.0 && offset <= 1e18) || voxels * bitsPerVoxel / 8 > 1e18) return std::nullopt;
  parsed.dataOffset = std::uint64_t(offset);
  parsed.dataBytes = std::uint64_t(voxels * bitsPerVoxel / 8);
  const unsigned char* magic = header.data() + (n2 ? 4 : 344);
  parsed.singleFile =
      magic[0] == 'n' && magic[1] == '+' && magic[2] == (n2 ? '2' : '1') && magic[3] == 0;
  parsed.sclSlope = n2 ? fieldAt<double>(header, 176, swap) : fieldAt<float>(header, 112, swap);
  parsed.sclInter = n2 ? fieldAt<double>(header, 184, swap) : fieldAt<float>(header, 116, swap);
  readPlacement(header, swap, parsed);
  return parsed;
}

}  // namespace

std::optional<NiftiHeader> readNiftiHeader(const std::filesystem::path& file) {
  gzFile gz = gzopen(file.c_str(), "rb");
  if (!gz) return std::nullopt;
  HeaderBytes header{};
  const int headerBytes = gzread(gz, header.data(), unsigned(header.size()));
  const bool compressed = gzdirect(gz) == 0;
  gzclose(gz);
  if (headerBytes < 348) return std::nullopt;
  for (bool swap : {false, true}) {
    if (auto result = parsed(header, headerBytes, swap)) {
      result->compressed = compressed;
      return result;
    }
  }
  return std::nullopt;
}

}  // namespace angio
