#include "io/nrrd_header.h"

#include <algorithm>
#include <fstream>
#include <string_view>

#include "io/lowercase.h"

namespace angio {

namespace {

// One line as airOneLine reads it, ending at LF, CR or CR LF; false at the end of the file (a last
// line without an end is still returned).
bool readLine(std::streambuf& in, std::string& line, std::uint64_t& offset, bool& endsWithCr) {
  line.clear();
  endsWithCr = false;
  for (int c = in.sbumpc(); c != std::char_traits<char>::eof(); c = in.sbumpc()) {
    ++offset;
    if (c == '\n') return true;
    if (c == '\r') {
      endsWithCr = true;
      if (in.sgetc() == '\n') {
        in.sbumpc();
        ++offset;
      }
      return true;
    }
    line += char(c);
  }
  return !line.empty();
}

// Teem parses a line as a C string: a NUL byte ends it. A comment starts with '#'; otherwise teem
// looks for a field ("name: value"), then for a key/value pair ("key:=value"). A ":=" before the
// first ": " cannot follow a field's name, so such a line is a key/value pair here; a ":=" after it
// may still be one for teem (if the name is no field), but is taken for a field, which is only
// checked more.
NrrdHeaderLine classified(std::string text, int number) {
  NrrdHeaderLine line;
  line.number = number;
  const std::string_view seen(text.c_str());
  const std::size_t separator = seen.find(": "), assign = seen.find(":=");
  if (!seen.empty() && seen[0] == '#') {
    line.kind = NrrdLineKind::comment;
  } else if (assign < separator) {
    line.kind = NrrdLineKind::keyValue;
  } else if (separator != std::string_view::npos) {
    line.kind = NrrdLineKind::field;
    line.name = lowercase(std::string(seen.substr(0, separator)));
    line.name.erase(
        std::remove_if(line.name.begin(), line.name.end(), [](char c) { return c == ' ' || c == '\t'; }),
        line.name.end());
    const std::string_view value = seen.substr(separator + 2);
    const std::size_t first = value.find_first_not_of(" \t");
    line.value = first == std::string_view::npos ? "" : std::string(value.substr(first));
  }
  line.text = std::move(text);
  return line;
}

}  // namespace

std::string NrrdHeader::field(const std::string& name, bool lowercased) const {
  for (auto line = lines.rbegin(); line != lines.rend(); ++line)
    if (line->kind == NrrdLineKind::field && line->name == name)
      return lowercased ? lowercase(line->value) : line->value;
  return "";
}

std::optional<NrrdHeader> readNrrdHeader(const std::filesystem::path& file) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) return std::nullopt;
  std::streambuf& in = *stream.rdbuf();
  std::string text;
  std::uint64_t offset = 0;
  bool endsWithCr = false;
  if (!readLine(in, text, offset, endsWithCr) || text.rfind("NRRD000", 0) != 0) return std::nullopt;
  NrrdHeader header;
  header.crLineEnds = endsWithCr;
  for (int number = 2; readLine(in, text, offset, endsWithCr); ++number) {
    header.crLineEnds = header.crLineEnds || endsWithCr;
    if (text.empty()) {
      header.dataStart = offset;
      break;
    }
    header.lines.push_back(classified(std::move(text), number));
    // Teem stops at a line it cannot read; past it may lie voxels without a blank line before.
    if (header.lines.back().kind == NrrdLineKind::unknown) break;
  }
  return header;
}

}  // namespace angio
