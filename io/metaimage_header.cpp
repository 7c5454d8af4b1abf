#include "io/metaimage_header.h"

#include <fstream>
#include <optional>
#include <string>

namespace angio {

namespace {

constexpr std::size_t kMaxLineBytes = 500;  // MetaIO's getline buffer
constexpr std::size_t kMaxKeyBytes = 255;   // MET_FieldRecordType::name
// MetaIO copies string values (ObjectType, Name, Comment, ElementDataFile, ...) with strcpy into
// 255-byte members of MetaObject and MetaImage.
constexpr std::size_t kMaxValueBytes = 255;

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  const auto last = text.find_last_not_of(" \t\r");
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

// Why MetaIO would not read `line` (the header's `number`th: field name `key`, `value`) as one
// field or not hold its value, or nullopt. A line without a separator makes MetaIO look for the next '=' or ':' further on (past
// ElementDataFile, into the voxels, where a long name overflows its 255-byte buffer).
std::optional<std::string> unreadableBy(const std::string& line, const std::string& key,
                                        const std::string& value, int number) {
  const std::string where = "header line " + std::to_string(number);
  if (line.size() >= kMaxLineBytes)
    return where + " has " + std::to_string(line.size()) + " characters (MetaIO reads " +
           std::to_string(kMaxLineBytes - 1) + ")";
  if (key.empty()) return where + " is not 'Key = Value'";
  if (key.size() >= kMaxKeyBytes)
    return where + " has a field name of " + std::to_string(key.size()) + " characters (MetaIO reads " +
           std::to_string(kMaxKeyBytes - 1) + ")";
  if (value.size() >= kMaxValueBytes)
    return where + " has a value of " + std::to_string(value.size()) + " characters (MetaIO keeps " +
           std::to_string(kMaxValueBytes - 1) + ")";
  return std::nullopt;
}

}  // namespace

std::string MetaImageHeader::field(const std::string& key) const {
  const auto found = fields.find(key);
  return found == fields.end() ? std::string() : found->second;
}

bool MetaImageHeader::flag(const std::string& key) const {
  const std::string value = field(key);
  return !value.empty() && (value[0] == 'T' || value[0] == 't' || value[0] == '1');
}

MetaImageHeader readMetaImageHeader(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  MetaImageHeader header;
  std::string line;
  // A header is a few dozen lines; the limit keeps a binary file from being scanned to its end.
  for (int lines = 1; lines <= 4096 && std::getline(in, line); ++lines) {
    if (trimmed(line).empty()) continue;
    // MetaIO ends a field's name at '=' or ':'; it reads a value with getline into 500 bytes.
    const auto separator = line.find_first_of("=:");
    // MetaIO compares names as C strings: a NUL ends one.
    const std::string name = separator == std::string::npos ? "" : line.substr(0, separator);
    const std::string key = trimmed(name.substr(0, name.find('\0')));
    const std::string value = separator == std::string::npos ? "" : trimmed(line.substr(separator + 1));
    if (!header.unreadableLine) header.unreadableLine = unreadableBy(line, key, value, lines);
    if (separator == std::string::npos) continue;
    if (header.fields.count(key)) header.repeated.insert(key);
    header.fields[key] = value;
    if (key != "ElementDataFile") continue;
    if (in) header.dataStart = std::uint64_t(in.tellg());
    header.dataLineEndsWithCr = !line.empty() && line.back() == '\r';
    break;
  }
  return header;
}

}  // namespace angio
