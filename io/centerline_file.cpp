#include "io/centerline_file.h"

#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "io/centerline_csv.h"
#include "io/centerline_markups.h"
#include "io/centerline_vtp.h"
#include "io/atomic_write.h"
#include "io/input_error.h"
#include "io/lowercase.h"

namespace angio {

namespace fs = std::filesystem;

namespace {

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

enum class CenterlineFormat { vtp, markups, csv };

std::optional<CenterlineFormat> formatOf(const fs::path& file) {
  const std::string name = lowercase(file.filename().string());
  if (endsWith(name, ".vtp")) return CenterlineFormat::vtp;
  if (endsWith(name, ".json")) return CenterlineFormat::markups;  // .mrk.json too
  if (endsWith(name, ".csv")) return CenterlineFormat::csv;
  return std::nullopt;
}

// Path names come from the file and may hold line breaks or other control characters (a quoted
// CSV field, a JSON string); messages stay one line with those shown as \n, \xNN.
std::string oneLine(const std::string& text) {
  std::string line;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      line += "\\n";
    } else if (c == '\r') {
      line += "\\r";
    } else if (byte < 0x20 || byte == 0x7F) {
      static constexpr char kHex[] = "0123456789ABCDEF";
      line += std::string("\\x") + kHex[byte >> 4] + kHex[byte & 15];
    } else {
      line += c;
    }
  }
  return line;
}

void warnEach(const Centerlines& centerlines, const std::vector<CenterlineIssue>& issues,
              const CenterlineLoadOptions& options) {
  if (!options.warn) return;
  for (const CenterlineIssue& issue : issues) {
    if (issue.severity == IssueSeverity::warning) options.warn(oneLine(describe(centerlines, issue)));
  }
}

// A path of one point has no direction or length: every use of centerlines (VesselGlyph, CPR,
// tracing comparisons) needs at least a segment, so such a file is refused where it is read.
void requireSegments(const Centerlines& centerlines, const fs::path& file) {
  for (std::size_t n = 0; n < centerlines.paths.size(); ++n) {
    const CenterlinePath& path = centerlines.paths[n];
    if (path.points.size() == 1) {
      throw InputError(file, oneLine("path '" + path.name + "' (number " + std::to_string(n + 1) +
                                     ") has a single point; a centerline path needs at least 2"));
    }
  }
}

}  // namespace

Centerlines loadCenterlines(const fs::path& file, const CenterlineLoadOptions& options) {
  const std::optional<CenterlineFormat> format = formatOf(file);
  if (format == CenterlineFormat::vtp) return readCenterlinesVtp(file, options);
  if (format == CenterlineFormat::markups) return readCenterlinesMarkups(file, options);
  if (format == CenterlineFormat::csv) return readCenterlinesCsv(file, options);
  throw InputError(file, "unknown centerline format (expected .vtp, .mrk.json, .json or .csv)");
}

void saveCenterlines(const Centerlines& centerlines, const fs::path& file) {
  const std::optional<CenterlineFormat> format = formatOf(file);
  if (format == CenterlineFormat::vtp) return writeCenterlinesVtp(centerlines, file);
  if (format == CenterlineFormat::markups) return writeCenterlinesMarkups(centerlines, file);
  if (format == CenterlineFormat::csv) return writeCenterlinesCsv(centerlines, file);
  throw InputError(file, "unknown centerline format (use .mrk.json, .vtp or .csv)");
}

void requireCenterlineTarget(const fs::path& file) {
  if (!formatOf(file)) throw InputError(file, "unknown centerline format (use .mrk.json, .vtp or .csv)");
  requireWritableTarget(file);
}

void checkLoadedCenterlines(const Centerlines& centerlines, const fs::path& file,
                            const CenterlineLoadOptions& options) {
  const std::vector<CenterlineIssue> issues = validateCenterlines(centerlines);
  for (const CenterlineIssue& issue : issues) {
    if (issue.severity == IssueSeverity::error) throw InputError(file, oneLine(issue.problem));
  }
  requireSegments(centerlines, file);
  warnEach(centerlines, issues, options);
}

void checkCenterlinesInside(const Centerlines& centerlines, const Volume& volume,
                            const CenterlineLoadOptions& options) {
  warnEach(centerlines, checkInsideVolume(centerlines, volume), options);
}

std::string readCenterlineFileBytes(const fs::path& file) {
  std::error_code error;
  if (!fs::exists(file, error)) throw InputError(file, "no such file");
  if (fs::is_directory(file, error)) throw InputError(file, "is a directory, not a file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "cannot open the file");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) throw InputError(file, "cannot read the file");
  return bytes.str();
}

void requirePhysicalFrame(const Centerlines& centerlines, const std::string& format) {
  if (centerlines.frame != CenterlineFrame::physical) {
    throw std::logic_error(format + " holds physical coordinates, not volume-frame ones");
  }
}

}  // namespace angio
