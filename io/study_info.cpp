#include "io/study_info.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace angio {

std::string trimmedDicomValue(const std::string& value) {
  const auto padding = [](char c) { return c == ' ' || c == '\0'; };
  const auto first = std::find_if_not(value.begin(), value.end(), padding);
  const auto last = std::find_if_not(value.rbegin(), value.rend(), padding).base();
  return first < last ? std::string(first, last) : std::string();
}

std::string readablePersonName(const std::string& dicomName) {
  const std::string alphabetic = dicomName.substr(0, dicomName.find('='));
  std::vector<std::string> parts;  // family, given, middle, prefix, suffix
  std::size_t start = 0;
  for (std::size_t caret = 0; caret != std::string::npos; start = caret + 1) {
    caret = alphabetic.find('^', start);
    parts.push_back(trimmedDicomValue(alphabetic.substr(start, caret - start)));
  }
  std::string given;
  for (std::size_t n = 1; n < std::min<std::size_t>(parts.size(), 3); ++n)
    if (!parts[n].empty()) given += (given.empty() ? "" : " ") + parts[n];
  if (parts[0].empty()) return given;
  return given.empty() ? parts[0] : parts[0] + ", " + given;
}

std::string readableDate(const std::string& dicomDate) {
  const std::string date = trimmedDicomValue(dicomDate);
  const bool digits = date.size() == 8 && std::all_of(date.begin(), date.end(), [](char c) {
                        return std::isdigit(static_cast<unsigned char>(c));
                      });
  if (!digits) return date;
  return date.substr(0, 4) + "-" + date.substr(4, 2) + "-" + date.substr(6, 2);
}

}  // namespace angio
