#include "io/metaimage_header.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
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

// A byte below 0x20 (or 0x7F) other than a tab, a NUL (a C-string end, read as MetaIO reads it) or
// the CR of a CRLF line end. MetaIO ends a field name at a CR and then takes the value after the
// next '=' (that may be on the line after), and skips a leading vertical tab or form feed;
// refusing these bytes keeps what this reader sees and what MetaIO sees the same.
std::optional<char> firstControlByte(const std::string& line) {
  const std::size_t end = !line.empty() && line.back() == '\r' ? line.size() - 1 : line.size();
  for (std::size_t at = 0; at < end; ++at) {
    const auto byte = static_cast<unsigned char>(line[at]);
    if ((byte < 0x20 || byte == 0x7F) && byte != '\t' && byte != '\0') return line[at];
  }
  return std::nullopt;
}

std::string byteText(char byte) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%02x", static_cast<unsigned char>(byte));
  return text;
}

// A field's name as MetaIO compares it: the text before the separator with the blanks at its end
// trimmed, then cut at a NUL (so "Name \0= x" is "Name ", but "Name\0 = x" is "Name").
std::string fieldName(std::string name) {
  name.erase(name.find_last_not_of(" \t") + 1);
  name.erase(std::min(name.find('\0'), name.size()));
  name.erase(0, std::min(name.find_first_not_of(" \t"), name.size()));
  return name;
}

// A field's value as MetaIO reads it: after the separator it skips every '=', ':' and blank, so
// "Name = : 12" is 12.
std::string valueText(const std::string& afterSeparator) {
  const std::size_t start = afterSeparator.find_first_not_of("=: \t");
  return start == std::string::npos ? "" : trimmed(afterSeparator.substr(start));
}

// Why MetaIO would not read `line` (the header's `number`th: field name `key`, `value`) as one
// field or not hold its value, or nullopt. A line without a separator makes MetaIO look for the next '=' or ':' further on (past
// ElementDataFile, into the voxels, where a long name overflows its 255-byte buffer).
std::optional<std::string> unreadableBy(const std::string& line, const std::string& key,
                                        const std::string& value, int number) {
  const std::string where = "header line " + std::to_string(number);
  if (const auto control = firstControlByte(line))
    return where + " has the control byte " + byteText(*control);
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

bool MetaImageHeader::flag(const std::string& key, bool absent) const {
  if (!fields.count(key)) return absent;
  const std::string value = field(key);
  return !value.empty() && (value[0] == 'T' || value[0] == 't' || value[0] == '1');
}

std::optional<double> MetaImageHeader::number(const std::string& key) const {
  const std::string value = field(key);
  char* end = nullptr;
  const double parsed = std::strtod(value.c_str(), &end);
  if (end == value.c_str()) return std::nullopt;
  return parsed;
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
    const std::string key = separator == std::string::npos ? "" : fieldName(line.substr(0, separator));
    const std::string value =
        separator == std::string::npos ? "" : valueText(line.substr(separator + 1));
    if (!header.unreadableLine) header.unreadableLine = unreadableBy(line, key, value, lines);
    if (separator == std::string::npos) continue;
    if (header.fields.count(key)) header.repeated.insert(key);
    header.fields[key] = value;
    if (key != "ElementDataFile") continue;
    // Nothing after the line (it ends the file): no data start, as for MetaIO.
    if (const std::streamoff at = in.tellg(); at >= 0) header.dataStart = std::uint64_t(at);
    break;
  }
  return header;
}

}  // namespace angio
