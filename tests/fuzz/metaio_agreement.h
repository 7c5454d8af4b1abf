#pragma once
// The differential half of the metaimage_header fuzz target: a header the checks before ITK accept
// (checkDeclaredGeometry) must read the same in MetaIO, ITK's MetaImage reader, since those checks
// judge what io/metaimage_header.h reads; and every spacing and origin MetaIO reads is usable. A
// disagreement is a finding: it aborts with both readings.
#include <metaImage.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/declared_geometry.h"
#include "io/input_error.h"
#include "io/metaimage_header.h"

namespace angio::fuzz {

// NDims, DimSize, the data file, binary or text, and the compression flag (with the compressed
// size: 0 for none, "impossible" for a negative one or one of 9e18 bytes and more), as one line.
inline std::string headerSummary(int dims, const std::string& sizes, const std::string& dataFile,
                                 bool binary, bool compressed, double compressedSize) {
  const std::string size = !(compressedSize >= 0 && compressedSize < 9e18)
                               ? std::string("impossible")
                               : std::to_string(std::uint64_t(compressedSize));
  return "NDims " + std::to_string(dims) + ", DimSize '" + sizes + "', ElementDataFile '" + dataFile +
         "', " + (binary ? "binary" : "text") + ", CompressedData " +
         (compressed ? "true, size " + size : std::string("false"));
}

// MetaIO's compressed size, which it keeps to itself.
struct MetaImageWithSizes : MetaImage {
  double compressedDataSize() const { return double(m_CompressedDataSize); }
};

inline void appendNumber(std::string& list, long number) {
  if (!list.empty()) list += ' ';
  list += std::to_string(number);
}

inline std::string ourSummary(const MetaImageHeader& header) {
  std::istringstream numbers(header.field("DimSize"));
  std::string sizes;
  for (double size = 0; numbers >> size;) appendNumber(sizes, long(size));
  return headerSummary(std::atoi(header.field("NDims").c_str()), sizes, header.field("ElementDataFile"),
                       header.flag("BinaryData", true), header.flag("CompressedData"),
                       header.number("CompressedDataSize").value_or(0));
}

inline std::string metaIoSummary(MetaImageWithSizes& image) {
  std::string sizes;
  for (int axis = 0; axis < image.NDims(); ++axis) appendNumber(sizes, image.DimSize(axis));
  return headerSummary(image.NDims(), sizes, image.ElementDataFileName(), image.BinaryData(),
                       image.CompressedData(), image.compressedDataSize());
}

// Where LOCAL voxel data start for io/ (MetaImageHeader::dataStart) and for MetaIO (its stream after
// the header), each as " data at N"; both "" where the header has no LOCAL data start.
struct DataStarts {
  std::string ours, metaIo;
};

inline DataStarts localDataStarts(const std::filesystem::path& file, const MetaImageHeader& header) {
  if (header.field("ElementDataFile") != "LOCAL" || !header.dataStart) return {};
  std::ifstream stream(file, std::ios::binary);
  MetaImage image;
  if (!image.ReadStream(0, &stream, false)) return {};
  return {" data at " + std::to_string(*header.dataStart),
          " data at " + std::to_string(static_cast<long long>(stream.tellg()))};
}

// An axis whose spacing (ElementSpacing, as ITK takes it) or origin MetaIO read unusable, or "".
inline std::string badGeometry(MetaImage& image) {
  for (int axis = 0; axis < image.NDims(); ++axis) {
    const double spacing = image.ElementSpacing(axis), origin = image.Position(axis);
    if (!(spacing > 0) || !std::isfinite(spacing) || !std::isfinite(origin))
      return ", axis " + std::to_string(axis) + " spacing " + std::to_string(spacing) + " origin " +
             std::to_string(origin);
  }
  return "";
}

inline void requireMetaIoAgrees(const std::filesystem::path& file, const MetaImageHeader& header) {
  try {
    checkDeclaredGeometry(file, VolumeFormat::metaImage);
  } catch (const InputError&) {
    return;  // refused before MetaIO would read it
  }
  MetaImageWithSizes image;
  if (!image.Read(file.c_str(), false)) return;  // MetaIO refuses it too
  const DataStarts starts = localDataStarts(file, header);
  const std::string metaIo = metaIoSummary(image) + badGeometry(image) + starts.metaIo;
  const std::string ours = ourSummary(header) + starts.ours;
  if (ours == metaIo) return;
  std::fprintf(stderr, "MetaIO reads the header otherwise:\n  ours:   %s\n  MetaIO: %s\n", ours.c_str(),
               metaIo.c_str());
  std::abort();
}

}  // namespace angio::fuzz
