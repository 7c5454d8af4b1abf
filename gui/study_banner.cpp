#include "gui/study_banner.h"

namespace angio {

namespace {

// The non-empty parts, three spaces apart.
std::string joined(const std::vector<std::string>& parts) {
  std::string line;
  for (const std::string& part : parts)
    if (!part.empty()) line += (line.empty() ? "" : "   ") + part;
  return line;
}

}  // namespace

std::vector<std::string> studyBanner(const StudyInfo& study) {
  std::vector<std::string> lines;
  const std::string who =
      joined({study.patientName, study.patientId.empty() ? "" : "ID " + study.patientId});
  const std::string what = joined({study.studyDate, study.seriesDescription, study.modality});
  for (const std::string& line : {who, what})
    if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace angio
