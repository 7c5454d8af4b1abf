#pragma once
// The fields of a NIfTI-1/-2 header (.nii, or .nii.gz: the same gzip-compressed) that say where
// the voxel data lies and how it is to be read, in either byte order.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>

namespace angio {

struct NiftiHeader {
  std::uint64_t dataOffset = 0;  // vox_offset: where the voxels start in the (decompressed) file
  std::uint64_t dataBytes = 0;   // all voxels of all dims, bitpix / 8 each
  bool nifti2 = false;
  bool swapped = false;     // written in the other byte order than this machine's
  bool compressed = false;  // the file is gzip (zlib's gz* functions read plain files too)
  bool singleFile = false;  // magic "n+1"/"n+2": header and data in one file
  double sclSlope = 0.0, sclInter = 0.0;
  // Where the voxels sit, as stored (ITK replaces a spacing it cannot use by 1 mm).
  std::array<double, 3> pixdim{};  // pixdim[1..3]: the voxel size
  int qformCode = 0, sformCode = 0;
  std::array<double, 6> qform{};   // quatern_b, c, d, qoffset_x, y, z
  std::array<double, 12> sform{};  // srow_x, srow_y, srow_z
};

// Empty if `file` cannot be read or holds no NIfTI header that makes sense.
std::optional<NiftiHeader> readNiftiHeader(const std::filesystem::path& file);

}  // namespace angio
