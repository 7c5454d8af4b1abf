#include "io/metaimage_header.h"

#include <fstream>

namespace angio {

namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  const auto last = text.find_last_not_of(" \t\r");
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

}  // namespace

std::string MetaImageHeader::field(const std::string& key) const {
  const auto found = fields.find(key);
  return found == fields.end() ? std::string() : found->second;
}

MetaImageHeader readMetaImageHeader(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  MetaImageHeader header;
  std::string line;
  // A header is a few dozen lines; the limit keeps a binary file from being scanned to its end.
  for (int lines = 0; lines < 4096 && std::getline(in, line); ++lines) {
    const auto equals = line.find('=');
    if (equals == std::string::npos) continue;
    const std::string key = trimmed(line.substr(0, equals));
    if (header.fields.count(key)) header.repeated.insert(key);
    header.fields[key] = trimmed(line.substr(equals + 1));
    if (key != "ElementDataFile") continue;
    if (in) header.dataStart = std::uint64_t(in.tellg());
    header.dataLineEndsWithCr = !line.empty() && line.back() == '\r';
    break;
  }
  return header;
}

}  // namespace angio
