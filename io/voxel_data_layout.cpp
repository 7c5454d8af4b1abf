#include "io/voxel_data_layout.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <string>

#include "io/lowercase.h"
#include "io/metaimage_header.h"
#include "io/nifti_header.h"

namespace angio {

namespace {

// A data file named in a header, if it is one plain file: no list, pattern or range of files.
bool namesOneFile(const std::string& name) {
  return !name.empty() && name != "LIST" && std::none_of(name.begin(), name.end(), [](unsigned char c) {
    return std::isspace(c) || c == '%';
  });
}

// ---- MetaImage: LOCAL data after the header, or one .raw/.zraw file beside it.
std::optional<VoxelDataLayout> metaImageLayout(const std::filesystem::path& file) {
  const MetaImageHeader header = readMetaImageHeader(file);
  const auto isOneOf = [&](const char* key, std::initializer_list<const char*> values) {
    return std::find(values.begin(), values.end(), header.field(key)) != values.end();
  };
  if (header.field("BinaryData") != "True") return std::nullopt;  // ASCII voxels
  if (!isOneOf("ElementByteOrderMSB", {"", "False"}) ||
      !isOneOf("BinaryDataByteOrderMSB", {"", "False"}))
    return std::nullopt;
  if (!isOneOf("CompressedData", {"", "False", "True"}) || !isOneOf("HeaderSize", {"", "0"}) ||
      !isOneOf("ElementNumberOfChannels", {"", "1"}))
    return std::nullopt;
  VoxelDataLayout layout;
  layout.encoding =
      header.field("CompressedData") == "True" ? VoxelEncoding::deflate : VoxelEncoding::raw;
  const std::string dataFile = header.field("ElementDataFile");
  if (dataFile == "LOCAL") {
    if (!header.dataStart || header.dataLineEndsWithCr) return std::nullopt;
    layout.dataFile = file;
    layout.fileOffset = *header.dataStart;
    return layout;
  }
  // MetaIO looks for a bare name beside the header; names with folders it resolves its own way.
  if (!namesOneFile(dataFile) || dataFile.find_first_of("/\\") != std::string::npos) return std::nullopt;
  layout.dataFile = file.parent_path() / dataFile;
  return layout;
}

// ---- NRRD: "field: value" lines after a NRRD000N magic line, ending with a blank line that the
// attached data follows; "data file" names detached data, relative to the header's folder.
struct NrrdHeader {
  std::map<std::string, std::string> fields;  // names without blanks: "datafile", "byteskip"
  std::optional<std::uint64_t> dataStart;     // after the blank line
  bool crlf = false;                          // some line ends in CR LF
};

std::optional<NrrdHeader> readNrrdHeader(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.rfind("NRRD000", 0) != 0) return std::nullopt;
  NrrdHeader header;
  for (int lines = 0; lines < 4096 && std::getline(in, line); ++lines) {
    if (!line.empty() && line.back() == '\r') {
      line.pop_back();
      header.crlf = true;
    }
    if (line.empty()) {
      if (in) header.dataStart = std::uint64_t(in.tellg());
      return header;
    }
    if (line[0] == '#' || line.find(":=") != std::string::npos) continue;  // comment, key/value
    const auto colon = line.find(": ");
    if (colon == std::string::npos) return std::nullopt;
    std::string name = lowercase(line.substr(0, colon));
    name.erase(std::remove(name.begin(), name.end(), ' '), name.end());
    header.fields[name] = line.substr(colon + 2);
  }
  return in.eof() ? std::optional(header)
                  : std::nullopt;  // a detached header may end without a blank line
}

// A header field's value ("" if absent); `lower`: as teem reads an enum, case-insensitively.
std::string nrrdField(const NrrdHeader& header, const char* name, bool lower = false) {
  const auto found = header.fields.find(name);
  if (found == header.fields.end()) return "";
  return lower ? lowercase(found->second) : found->second;
}

std::optional<VoxelDataLayout> nrrdPlace(const std::filesystem::path& file, const NrrdHeader& header) {
  VoxelDataLayout layout;
  const std::string encoding = nrrdField(header, "encoding", true);
  if (encoding == "gzip" || encoding == "gz") {
    layout.encoding = VoxelEncoding::deflate;
  } else if (encoding != "raw") {
    return std::nullopt;
  }
  for (const char* skip : {"lineskip", "byteskip"})
    if (!nrrdField(header, skip).empty() && nrrdField(header, skip) != "0") return std::nullopt;
  const std::string dataFile = nrrdField(header, "datafile");
  if (dataFile.empty()) {
    if (!header.dataStart) return std::nullopt;
    layout.dataFile = file;
    layout.fileOffset = *header.dataStart;
    return layout;
  }
  if (!namesOneFile(dataFile)) return std::nullopt;
  const std::filesystem::path data(dataFile);
  layout.dataFile = data.is_absolute() ? data : file.parent_path() / data;
  return layout;
}

std::optional<VoxelDataLayout> nrrdLayout(const std::filesystem::path& file,
                                          const StoredDataSize& size) {
  const auto header = readNrrdHeader(file);
  if (!header || header->crlf) return std::nullopt;  // CRLF: teem reads the voxels
  const std::string endian = nrrdField(*header, "endian", true);
  if (endian != "little" && !(endian.empty() && size.componentBytes == 1)) return std::nullopt;
  return nrrdPlace(file, *header);
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

std::optional<VoxelDataLayout> nrrdDataPlace(const std::filesystem::path& file) {
  const auto header = readNrrdHeader(file);
  return header ? nrrdPlace(file, *header) : std::nullopt;
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
