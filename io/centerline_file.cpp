#include "io/centerline_file.h"

#include <fstream>
#include <sstream>

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

void warnEach(const Centerlines& centerlines, const std::vector<CenterlineIssue>& issues,
              const CenterlineLoadOptions& options) {
  if (!options.warn) return;
  for (const CenterlineIssue& issue : issues) {
    if (issue.severity == IssueSeverity::warning) options.warn(describe(centerlines, issue));
  }
}

}  // namespace

Centerlines loadCenterlines(const fs::path& file, const CenterlineLoadOptions& options) {
  const std::string name = lowercase(file.filename().string());
  if (endsWith(name, ".vtp")) return readCenterlinesVtp(file, options);
  if (endsWith(name, ".json")) return readCenterlinesMarkups(file, options);  // .mrk.json too
  if (endsWith(name, ".csv")) return readCenterlinesCsv(file, options);
  throw InputError(file, "unknown centerline format (expected .vtp, .mrk.json, .json or .csv)");
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

}  // namespace angio
