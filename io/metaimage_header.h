#pragma once
// A MetaImage (.mha/.mhd) header as text fields: "Key = Value" (or "Key: Value") lines up to
// ElementDataFile, which MetaIO requires to be the last field; LOCAL voxel data starts on the line
// after it.
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <optional>
#include <string>

namespace angio {

struct MetaImageHeader {
  std::map<std::string, std::string> fields;  // values trimmed of blanks; the last of a repeated key
  std::set<std::string> repeated;             // keys the header has more than once
  // Offset of the byte after the ElementDataFile line; empty if the header has no such line.
  std::optional<std::uint64_t> dataStart;
  // The first line MetaIO would not read as one "Key = Value" field or whose value it would not
  // hold, and why ("header line 4 is not 'Key = Value'"); MetaIO's reading goes astray there (and
  // its buffers overflow).
  std::optional<std::string> unreadableLine;

  // The field's value, or "" if the header does not have it.
  std::string field(const std::string& key) const;
  // A boolean field as MetaIO reads it: true iff its value starts with T, t or 1; `absent` if the
  // header does not have it (MetaIO's default: true for BinaryData, false for the others).
  bool flag(const std::string& key, bool absent = false) const;
  // A number field as MetaIO reads it: a double, up to the first character that is not part of
  // one ("12abc" is 12); nullopt if the value does not start with a number.
  std::optional<double> number(const std::string& key) const;
};

MetaImageHeader readMetaImageHeader(const std::filesystem::path& file);

}  // namespace angio
