#include "io/centerline_file.h"

#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "io/centerline_csv.h"
#include "io/centerline_markups.h"
#include "io/centerline_vtp.h"
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

void warnEach(const Centerlines& centerlines, const std::vector<CenterlineIssue>& issues,
              const CenterlineLoadOptions& options) {
  if (!options.warn) return;
  for (const CenterlineIssue& issue : issues) {
    if (issue.severity == IssueSeverity::warning) options.warn(describe(centerlines, issue));
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

void checkLoadedCenterlines(const Centerlines& centerlines, const fs::path& file,
                            const CenterlineLoadOptions& options) {
  const std::vector<CenterlineIssue> issues = validateCenterlines(centerlines);
  for (const CenterlineIssue& issue : issues) {
    if (issue.severity == IssueSeverity::error) throw InputError(file, issue.problem);
  }
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
