#pragma once
// A NRRD header's lines as teem reads them (airOneLine, _nrrdReadNrrdParseField), for the checks
// made before teem reads a file (declared_geometry.h) and for where io/ finds its voxel data
// (voxel_data_layout.h): the magic line "NRRD000N", then lines up to an empty one, after which
// attached data start (a detached header may end at the end of the file instead). A line ends at
// LF, CR or CR LF.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace angio {

enum class NrrdLineKind {
  comment,   // starts with '#'
  keyValue,  // "key:=value" (teem's key/value pairs: Slicer's segment metadata)
  field,     // "name: value"
  unknown,   // none of these; teem refuses the file
};

struct NrrdHeaderLine {
  int number = 0;  // counting the magic line as line 1
  NrrdLineKind kind = NrrdLineKind::unknown;
  std::string text;   // the whole line without its end
  std::string name;   // a field's name as teem matches it: lowercase, blanks removed ("datafile")
  std::string value;  // a field's value, leading blanks removed

  bool operator==(const NrrdHeaderLine&) const = default;
};

struct NrrdHeader {
  std::vector<NrrdHeaderLine> lines;       // after the magic line
  std::optional<std::uint64_t> dataStart;  // after the empty line; none in a detached header
  bool crLineEnds = false;                 // some line ends in CR (or CR LF)

  // The last value of the field `name` (as NrrdHeaderLine::name), or "" if the header lacks it;
  // `lowercased` for the values teem reads case-insensitively (encoding, endian).
  std::string field(const std::string& name, bool lowercased = false) const;

  bool operator==(const NrrdHeader&) const = default;
};

// Nothing if the file does not start with the magic line or cannot be read.
std::optional<NrrdHeader> readNrrdHeader(const std::filesystem::path& file);

}  // namespace angio
