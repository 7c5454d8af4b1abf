#pragma once
// Text from a file as messages show it, the one rule for every reader: printable ASCII and valid
// UTF-8 characters as they are, every other byte (line breaks, control characters, binary) as
// \xNN, so that a message stays on one line whatever the file holds; at most maxBytes bytes of
// it, then "...".
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

namespace angio {

// The length (2-4) of the well-formed UTF-8 character that starts at text[at], or 0.
inline std::size_t utf8CharacterAt(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t n) { return static_cast<unsigned char>(text[n]); };
  const unsigned char lead = byte(at);
  const std::size_t length = lead >= 0xC2 && lead <= 0xDF   ? 2
                             : lead >= 0xE0 && lead <= 0xEF ? 3
                             : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                            : 0;
  if (length == 0 || at + length > text.size()) return 0;
  for (std::size_t n = at + 1; n < at + length; ++n)
    if ((byte(n) & 0xC0) != 0x80) return 0;
  return length;
}

inline std::string shownText(std::string_view text, std::size_t maxBytes = 80) {
  const std::string_view kept = text.substr(0, maxBytes);
  std::string shown;
  for (std::size_t at = 0; at < kept.size();) {
    const auto byte = static_cast<unsigned char>(kept[at]);
    if (byte >= 0x20 && byte < 0x7F) {
      shown += kept[at++];
    } else if (const std::size_t length = utf8CharacterAt(kept, at); length > 0) {
      shown += kept.substr(at, length);
      at += length;
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      shown += escaped;
      ++at;
    }
  }
  return text.size() > maxBytes ? shown + "..." : shown;
}

// ... in single quotes.
inline std::string quotedText(std::string_view text) {
  std::string quoted = shownText(text);
  quoted.insert(quoted.begin(), '\'');  // (not "'" + shownText(): GCC 12 warns of a false overlap)
  return quoted + '\'';
}

}  // namespace angio
