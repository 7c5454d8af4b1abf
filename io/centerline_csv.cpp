#include "io/centerline_csv.h"

#include <charconv>
#include <map>
#include <string_view>
#include <vector>

#include "io/atomic_write.h"
#include "io/input_error.h"
#include "io/shown_text.h"
#include "io/number_text.h"

namespace angio {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kHeader = "path,x_mm,y_mm,z_mm,radius_mm";

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string lineText(int line) { return "line " + std::to_string(line); }

// --- Writing ------------------------------------------------------------------------------------

// RFC 4180 quoting where a field needs it; also for leading or trailing spaces, which the reader
// trims from unquoted fields.
std::string csvField(const std::string& text) {
  const bool plain = !text.empty() && text.find_first_of(",\"\r\n") == std::string::npos &&
                     !isSpace(text.front()) && !isSpace(text.back());
  if (plain) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + '"';
}

// Each path's id, the name or else the index; two equal ids would merge the paths on reading.
std::vector<std::string> pathIds(const Centerlines& centerlines, const fs::path& file) {
  std::vector<std::string> ids;
  std::map<std::string, std::size_t> pathOfId;
  for (std::size_t p = 0; p < centerlines.paths.size(); ++p) {
    const std::string& name = centerlines.paths[p].name;
    ids.push_back(name.empty() ? std::to_string(p) : name);
    const auto [found, added] = pathOfId.emplace(ids.back(), p);
    if (!added) {
      throw InputError(file, "paths " + std::to_string(found->second) + " and " + std::to_string(p) +
                                 " would both be written as path '" + ids.back() +
                                 "' (a CSV file groups rows by path, so each needs a name of its own)");
    }
  }
  return ids;
}

std::string csvText(const Centerlines& centerlines, const fs::path& file) {
  const std::vector<std::string> ids = pathIds(centerlines, file);
  std::string text = std::string(kHeader) + '\n';
  for (std::size_t p = 0; p < centerlines.paths.size(); ++p) {
    const std::string id = csvField(ids[p]);
    for (const CenterlinePoint& point : centerlines.paths[p].points) {
      text += id + ',' + numberText(point.positionMm.x) + ',' + numberText(point.positionMm.y) + ',' +
              numberText(point.positionMm.z) + ',' + numberText(point.radiusMm) + '\n';
    }
  }
  return text;
}

// --- Reading ------------------------------------------------------------------------------------

struct Record {
  int line = 0;  // 1-based, where the record starts
  std::vector<std::string> fields;
};

void skipSpaces(std::string_view text, std::size_t& position) {
  while (position < text.size() && isSpace(text[position])) ++position;
}

// A field in double quotes, from its opening quote; "" is a quote, line breaks are kept (and
// counted in `line`).
std::string quotedField(std::string_view text, std::size_t& position, int& line,
                        const fs::path& source) {
  const int startLine = line;
  std::string field;
  for (++position;; ++position) {
    if (position >= text.size())
      throw InputError(source, lineText(startLine) + ": quoted field not closed");
    if (text[position] == '"') {
      if (position + 1 == text.size() || text[position + 1] != '"') break;
      ++position;
    }
    if (text[position] == '\n') ++line;
    field += text[position];
  }
  ++position;  // the closing quote
  skipSpaces(text, position);
  if (position < text.size() && text[position] != ',' && text[position] != '\n') {
    throw InputError(source, lineText(line) + ": text after the closing quote");
  }
  return field;
}

// One field from `position`, which is left at the comma, line break or end after it. Unquoted
// fields are trimmed of spaces (and of the '\r' of CRLF line ends).
std::string nextField(std::string_view text, std::size_t& position, int& line, const fs::path& source) {
  skipSpaces(text, position);
  if (position < text.size() && text[position] == '"') return quotedField(text, position, line, source);
  const std::size_t end = std::min(text.find_first_of(",\n", position), text.size());
  std::size_t last = end;
  while (last > position && isSpace(text[last - 1])) --last;
  std::string field(text.substr(position, last - position));
  position = end;
  return field;
}

// The records of RFC 4180 text, blank lines left out.
std::vector<Record> csvRecords(std::string_view text, const fs::path& source) {
  std::vector<Record> records;
  int line = 1;
  for (std::size_t position = 0; position < text.size(); ++position, ++line) {
    Record record{line, {nextField(text, position, line, source)}};
    while (position < text.size() && text[position] == ',') {
      ++position;
      record.fields.push_back(nextField(text, position, line, source));
    }
    if (record.fields.size() > 1 || !record.fields.front().empty()) records.push_back(std::move(record));
  }
  return records;
}

// from_chars takes "nan" and "inf" too; the model's validation reports those with the path.
double parseNumber(std::string_view field, const fs::path& source, int line) {
  double value = 0;
  const char* first = field.data();
  const char* last = field.data() + field.size();
  if (!field.empty() && *first == '+') ++first;
  const auto [end, error] = std::from_chars(first, last, value);
  if (error != std::errc() || end != last || field.empty()) {
    throw InputError(source, lineText(line) + ": " + quotedText(field) + " is not a number");
  }
  return value;
}

void checkHeader(const Record& header, const fs::path& source) {
  std::string columns;
  for (const std::string& field : header.fields) columns += (columns.empty() ? "" : ",") + field;
  if (columns != kHeader) {
    throw InputError(source,
                     lineText(header.line) + ": expected the header '" + std::string(kHeader) + "'");
  }
}

CenterlinePoint parsePoint(const Record& record, const fs::path& source) {
  const glm::dvec3 position{parseNumber(record.fields[1], source, record.line),
                            parseNumber(record.fields[2], source, record.line),
                            parseNumber(record.fields[3], source, record.line)};
  return {position, parseNumber(record.fields[4], source, record.line)};
}

}  // namespace

void writeCenterlinesCsv(const Centerlines& centerlines, const fs::path& file) {
  requirePhysicalFrame(centerlines, "centerline CSV");
  writeBytesAtomically(file, csvText(centerlines, file));
}

Centerlines parseCenterlinesCsv(const std::string& text, const fs::path& source,
                                const CenterlineLoadOptions& options) {
  const std::vector<Record> records = csvRecords(text, source);
  if (records.empty()) throw InputError(source, "empty file (no header line)");
  checkHeader(records.front(), source);

  Centerlines centerlines;
  centerlines.source = source.string();
  std::map<std::string, std::size_t, std::less<>> pathOfId;
  for (std::size_t n = 1; n < records.size(); ++n) {
    const Record& record = records[n];
    if (record.fields.size() != 5) {
      throw InputError(source, lineText(record.line) + ": " + std::to_string(record.fields.size()) +
                                   " fields, expected 5");
    }
    const std::string& id = record.fields[0];
    if (id.empty()) throw InputError(source, lineText(record.line) + ": no path id");
    const auto [found, added] = pathOfId.emplace(id, centerlines.paths.size());
    if (added) centerlines.paths.push_back({id, {}});
    centerlines.paths[found->second].points.push_back(parsePoint(record, source));
  }
  checkLoadedCenterlines(centerlines, source, options);
  return centerlines;
}

Centerlines readCenterlinesCsv(const fs::path& file, const CenterlineLoadOptions& options) {
  return parseCenterlinesCsv(readCenterlineFileBytes(file), file, options);
}

}  // namespace angio
