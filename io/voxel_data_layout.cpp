#include "io/voxel_data_layout.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <utility>

#include "io/input_error.h"
#include "io/lowercase.h"
#include "io/metaimage_header.h"
#include "io/nifti_header.h"
#include "io/nrrd_header.h"

namespace angio {

namespace {

// A data file named in a header, if it is one plain file: no list, pattern or range of files.
bool namesOneFile(const std::string& name) {
  return !name.empty() && name != "LIST" && std::none_of(name.begin(), name.end(), [](unsigned char c) {
    return std::isspace(c) || c == '%';
  });
}

// ---- MetaImage: LOCAL data after the header, or one .raw/.zraw file, named relative to the
// header's folder (as MetaIO resolves it) or absolute.
struct MetaImagePlace {
  std::optional<VoxelDataLayout> layout;
  std::string leftToMetaIo;  // why there is no layout: "in big-endian byte order"
};

MetaImagePlace metaImagePlace(const std::filesystem::path& file, const MetaImageHeader& header) {
  const auto isOneOf = [&](const char* key, std::initializer_list<const char*> values) {
    return std::find(values.begin(), values.end(), header.field(key)) != values.end();
  };
  // MetaIO reads a flag by its first letter, and binary data where the header does not say.
  if (!header.flag("BinaryData", true)) return {{}, "as text"};
  if (header.flag("ElementByteOrderMSB") || header.flag("BinaryDataByteOrderMSB"))
    return {{}, "in big-endian byte order"};
  if (!isOneOf("HeaderSize", {"", "0"})) return {{}, "after a HeaderSize"};
  if (!isOneOf("ElementNumberOfChannels", {"", "1"})) return {{}, "with several channels per voxel"};
  VoxelDataLayout layout;
  layout.encoding = header.flag("CompressedData") ? VoxelEncoding::deflate : VoxelEncoding::raw;
  layout.libraryMayRetry = layout.encoding == VoxelEncoding::raw;
  const std::string dataFile = header.field("ElementDataFile");
  if (dataFile == "LOCAL") {
    if (!header.dataStart) return {{}, "missing after the header"};
    layout.dataFile = file;
    layout.fileOffset = *header.dataStart;
    return {layout, ""};
  }
  if (!namesOneFile(dataFile)) return {{}, "in a list or pattern of files"};
  const std::filesystem::path data(dataFile);
  layout.dataFile = data.is_absolute() ? data : file.parent_path() / data;
  return {layout, ""};
}

std::optional<VoxelDataLayout> metaImageLayout(const std::filesystem::path& file) {
  const MetaImageHeader header = readMetaImageHeader(file);
  MetaImagePlace place = metaImagePlace(file, header);
  // MetaIO's inflate loop (MET_PerformUncompression) takes zlib's "needs a preset dictionary" for
  // progress and never ends, so compressed data are never left to it.
  if (!place.layout && header.flag("BinaryData", true) && header.flag("CompressedData"))
    throw InputError(file, "has compressed voxel data " + place.leftToMetaIo +
                               ", which angioray does not read (compressed data must be one "
                               "little-endian block of single-channel voxels)");
  return std::move(place.layout);
}

// ---- NRRD: attached data after the header's empty line, or one "data file" relative to the
// header's folder.
std::optional<NrrdDataStart> nrrdStart(const std::filesystem::path& file, const NrrdHeader& header) {
  const bool unreadable = std::any_of(header.lines.begin(), header.lines.end(), [](const auto& line) {
    return line.kind == NrrdLineKind::unknown;
  });
  if (unreadable) return std::nullopt;  // teem refuses it
  NrrdDataStart start;
  start.encoding = header.field("encoding", true);
  const std::string dataFile = header.field("datafile");
  if (dataFile.empty()) {
    if (!header.dataStart) return std::nullopt;
    start.dataFile = file;
    start.fileOffset = *header.dataStart;
    return start;
  }
  if (!namesOneFile(dataFile)) return std::nullopt;
  const std::filesystem::path data(dataFile);
  start.dataFile = data.is_absolute() ? data : file.parent_path() / data;
  return start;
}

std::optional<VoxelDataLayout> nrrdPlace(const NrrdHeader& header,
                                         const std::optional<NrrdDataStart>& start) {
  if (!start) return std::nullopt;
  for (const char* skip : {"lineskip", "byteskip"})
    if (!header.field(skip).empty() && header.field(skip) != "0") return std::nullopt;
  VoxelDataLayout layout;
  if (start->encoding == "gzip" || start->encoding == "gz") {
    layout.encoding = VoxelEncoding::deflate;
  } else if (start->encoding != "raw") {
    return std::nullopt;
  }
  layout.dataFile = start->dataFile;
  layout.fileOffset = start->fileOffset;
  return layout;
}

std::optional<VoxelDataLayout> nrrdLayout(const std::filesystem::path& file,
                                          const StoredDataSize& size) {
  const auto header = readNrrdHeader(file);
  if (!header || header->crLineEnds) return std::nullopt;  // teem reads the voxels
  const std::string endian = header->field("endian", true);
  if (endian != "little" && !(endian.empty() && size.componentBytes == 1)) return std::nullopt;
  return nrrdPlace(*header, nrrdStart(file, *header));
}

// ---- NIfTI-1 single file: voxels at vox_offset (of the decompressed stream for .nii.gz).
// ITK's NIfTI library opens x.nii in place of x.nii.gz when both exist (header and voxels);
// reading the .gz here would mix the two files.
bool hasUncompressedTwin(const std::filesystem::path& file) {
  const std::string name = file.string();
  if (lowercase(file.extension().string()) != ".gz") return false;
  std::error_code error;
  return std::filesystem::exists(name.substr(0, name.size() - 3), error) || error;
}

std::optional<VoxelDataLayout> niftiLayout(const std::filesystem::path& file,
                                           const StoredDataSize& size) {
  if (hasUncompressedTwin(file)) return std::nullopt;
  const auto header = readNiftiHeader(file);
  if (!header || header->nifti2 || header->swapped || !header->singleFile) return std::nullopt;
  // ITK scales the values unless the slope is 0 (none) or 1 with no intercept.
  const bool scaled = !((header->sclSlope == 0.0 || header->sclSlope == 1.0) && header->sclInter == 0.0);
  // vox_offset below the 352-byte header is corrected by the NIfTI library; leave that to it.
  if (scaled || header->dataOffset < 352 || header->dataBytes != size.voxelBytes) return std::nullopt;
  VoxelDataLayout layout;
  layout.dataFile = file;
  if (header->compressed) {
    layout.encoding = VoxelEncoding::deflate;
    layout.skipBytes = header->dataOffset;
  } else {
    layout.fileOffset = header->dataOffset;
  }
  return layout;
}

}  // namespace

NrrdData nrrdData(const std::filesystem::path& file) {
  const auto header = readNrrdHeader(file);
  if (!header) return {};
  NrrdData data;
  data.start = nrrdStart(file, *header);
  data.place = nrrdPlace(*header, data.start);
  return data;
}

std::optional<VoxelDataLayout> voxelDataLayout(const std::filesystem::path& file, VolumeFormat format,
                                               const StoredDataSize& size) {
  switch (format) {
    case VolumeFormat::metaImage: return metaImageLayout(file);
    case VolumeFormat::nrrd: return nrrdLayout(file, size);
    case VolumeFormat::nifti: return niftiLayout(file, size);
  }
  return std::nullopt;
}

}  // namespace angio
