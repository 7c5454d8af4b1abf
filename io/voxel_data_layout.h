#pragma once
// Where a single-file volume's voxel bytes lie (MetaImage, NRRD, NIfTI), read from its header, for
// the files whose voxels io/ decodes itself (voxel_slab_reader.h): one block, raw or one zlib/gzip
// stream, in this machine's byte order, holding exactly the values ITK would return. Anything else
// (ASCII or bzip2 data, file lists, line or byte skips, the other byte order, NIfTI scaling, which
// ITK applies while reading) has no layout here and is left to ITK's own reader; but not
// compressed MetaImage data, which are refused instead.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "io/volume_formats.h"

namespace angio {

enum class VoxelEncoding {
  raw,
  deflate,  // a zlib or gzip stream (or several gzip members), told apart by its first bytes
};

struct VoxelDataLayout {
  std::filesystem::path dataFile;
  std::uint64_t fileOffset = 0;  // where the raw data or the compressed stream starts
  VoxelEncoding encoding = VoxelEncoding::raw;
  std::uint64_t skipBytes = 0;  // decoded bytes before the first voxel (a .nii.gz's header)
  // Whether the library may read the data again when io/ finds them damaged, so that its own
  // message is shown: not MetaIO's compressed data (its inflate loop never ends on some).
  bool libraryMayRetry = true;
};

// The voxel data's size as ITK reports it for the header.
struct StoredDataSize {
  std::uint64_t voxelBytes = 0;
  unsigned componentBytes = 0;
};

// Throws InputError for compressed MetaImage data it has no layout for (MetaIO may never return
// from reading those).
std::optional<VoxelDataLayout> voxelDataLayout(const std::filesystem::path& file, VolumeFormat format,
                                               const StoredDataSize& size);

// Where a NRRD's voxel data start in any encoding (attached or in one data file), before any line
// or byte skip, and the encoding as the header names it ("ascii", "hex", ...).
struct NrrdDataStart {
  std::filesystem::path dataFile;
  std::uint64_t fileOffset = 0;
  std::string encoding;
};

// From one reading of a NRRD header: where its data start (nothing for lists of files), and where
// they lie whatever their byte order, as a layout only where io/ reads them too (raw or gzip, no
// line or byte skips).
struct NrrdData {
  std::optional<NrrdDataStart> start;
  std::optional<VoxelDataLayout> place;
};
NrrdData nrrdData(const std::filesystem::path& file);

}  // namespace angio
