#pragma once
// ASCII lowercase, for the case-insensitive names io/ accepts: file extensions, preset names,
// the Markups "Radius" measurement.
#include <algorithm>
#include <cctype>
#include <string>

namespace angio {

inline std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

}  // namespace angio
