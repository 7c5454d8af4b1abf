#include "io/centerline_csv.h"

#include <charconv>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "io/atomic_write.h"
#include "io/input_error.h"

namespace angio {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kHeader = "path,x_mm,y_mm,z_mm,radius_mm";

void writeRows(const Centerlines& centerlines, std::ostream& out) {
  out << kHeader << '\n';
  char row[160];
  for (std::size_t p = 0; p < centerlines.paths.size(); ++p) {
    for (const CenterlinePoint& point : centerlines.paths[p].points) {
      // Three decimals (micrometres), as in the reference file; snprintf is locale-independent
      // for the "C" locale the program runs in.
      std::snprintf(row, sizeof row, "%zu,%.3f,%.3f,%.3f,%.3f\n", p, point.positionMm.x,
                    point.positionMm.y, point.positionMm.z, point.radiusMm);
      out << row;
    }
  }
}

std::string_view trimmed(std::string_view text) {
  const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
  while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
  return text;
}

std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trimmed(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

// Lines with their 1-based numbers, blank lines left out.
std::vector<std::pair<int, std::string_view>> nonBlankLines(std::string_view text) {
  std::vector<std::pair<int, std::string_view>> lines;
  int number = 0;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    ++number;
    const std::string_view line = trimmed(text.substr(start, end - start));
    if (!line.empty()) lines.emplace_back(number, line);
    start = end + 1;
  }
  return lines;
}

// from_chars takes "nan" and "inf" too; the model's validation reports those with the path.
double parseNumber(std::string_view field, const fs::path& source, int line) {
  double value = 0;
  const char* first = field.data();
  const char* last = field.data() + field.size();
  if (!field.empty() && *first == '+') ++first;
  const auto [end, error] = std::from_chars(first, last, value);
  if (error != std::errc() || end != last || field.empty()) {
    throw InputError(source,
                     "line " + std::to_string(line) + ": '" + std::string(field) + "' is not a number");
  }
  return value;
}

void checkHeader(std::string_view header, const fs::path& source, int line) {
  std::string columns;
  for (std::string_view field : splitFields(header)) {
    if (!columns.empty()) columns += ',';
    columns += field;
  }
  if (columns != kHeader) {
    throw InputError(
        source, "line " + std::to_string(line) + ": expected the header '" + std::string(kHeader) + "'");
  }
}

}  // namespace

void writeCenterlinesCsv(const Centerlines& centerlines, const fs::path& file) {
  if (centerlines.frame != CenterlineFrame::physical) {
    throw std::logic_error("centerline CSV holds physical coordinates, not volume-frame ones");
  }
  writeAtomically(file, [&](const fs::path& temp) {
    std::ofstream out(temp, std::ios::binary);
    if (!out) throw InputError(file, "cannot open for writing");
    writeRows(centerlines, out);
    out.flush();
    if (!out) throw InputError(file, "write failed");
  });
}

Centerlines parseCenterlinesCsv(const std::string& text, const fs::path& source,
                                const CenterlineLoadOptions& options) {
  const auto lines = nonBlankLines(text);
  if (lines.empty()) throw InputError(source, "empty file (no header line)");
  checkHeader(lines.front().second, source, lines.front().first);

  Centerlines centerlines;
  centerlines.source = source.string();
  std::map<std::string, std::size_t, std::less<>> pathOfId;
  for (std::size_t n = 1; n < lines.size(); ++n) {
    const auto [line, row] = lines[n];
    const std::vector<std::string_view> fields = splitFields(row);
    if (fields.size() != 5) {
      throw InputError(source, "line " + std::to_string(line) + ": " + std::to_string(fields.size()) +
                                   " fields, expected 5");
    }
    if (fields[0].empty()) throw InputError(source, "line " + std::to_string(line) + ": no path id");
    auto found = pathOfId.find(fields[0]);
    if (found == pathOfId.end()) {
      found = pathOfId.emplace(std::string(fields[0]), centerlines.paths.size()).first;
      centerlines.paths.push_back({std::string(fields[0]), {}});
    }
    const glm::dvec3 position{parseNumber(fields[1], source, line), parseNumber(fields[2], source, line),
                              parseNumber(fields[3], source, line)};
    centerlines.paths[found->second].points.push_back({position, parseNumber(fields[4], source, line)});
  }
  checkLoadedCenterlines(centerlines, source, options);
  return centerlines;
}

Centerlines readCenterlinesCsv(const fs::path& file, const CenterlineLoadOptions& options) {
  return parseCenterlinesCsv(readCenterlineFileBytes(file), file, options);
}

}  // namespace angio
