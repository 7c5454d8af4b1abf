#pragma once
// Text from a file as error messages quote it: one line (line breaks and control characters as
// \n, \xNN), at most 80 characters, in single quotes.
#include <string>
#include <string_view>

namespace angio {

inline std::string quotedText(std::string_view text) {
  constexpr char kHex[] = "0123456789ABCDEF";
  std::string shown = "'";
  for (const char c : text.substr(0, 80)) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      shown += "\\n";
    } else if (byte < 0x20 || byte == 0x7F) {
      shown += std::string("\\x") + kHex[byte >> 4] + kHex[byte & 15];
    } else {
      shown += c;
    }
  }
  return shown + (text.size() > 80 ? "...'" : "'");
}

}  // namespace angio
