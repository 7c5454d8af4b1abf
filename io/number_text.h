#pragma once
// Numbers in the text file formats (CSV, .vtp): the shortest decimal that reads back as the same
// double, independent of the locale.
#include <charconv>
#include <cmath>
#include <string>

namespace angio {

// Plain decimals where they are short, as JavaScript prints numbers ("-0.0004", "0.1",
// "-218.4904022216797"), exponents only for the very large and very small ("1e+21", "5e-07");
// -0 is written as "0" (+ 0.0 drops the sign).
inline std::string numberText(double value) {
  char text[64];
  const double magnitude = std::fabs(value);
  const bool plain = magnitude == 0 || (magnitude >= 1e-6 && magnitude < 1e21);
  const auto end = plain ? std::to_chars(text, text + sizeof text, value + 0.0, std::chars_format::fixed)
                         : std::to_chars(text, text + sizeof text, value);
  return std::string(text, end.ptr);
}

}  // namespace angio
