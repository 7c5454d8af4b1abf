#include "cli/number_list.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace angio {

std::vector<double> parseNumberList(const std::string& text, std::size_t count, const std::string& flag,
                                    const std::string& form) {
  const std::string usage = flag + " needs " + form + ", got '" + text + "'";
  std::vector<double> values;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(value)) throw std::invalid_argument(usage);
    values.push_back(value);
    at = comma + 1;
  }
  if (values.size() != count) throw std::invalid_argument(usage);
  return values;
}

}  // namespace angio
