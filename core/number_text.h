#pragma once
// A number as text for metadata and sidecars: up to 10 significant digits, no trailing zeros.
#include <sstream>
#include <string>

namespace angio {

inline std::string numberText(double value) {
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

}  // namespace angio
