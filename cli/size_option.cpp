#include "cli/size_option.h"

#include <regex>
#include <stdexcept>

namespace angio {

glm::ivec3 parseSize(const std::string& text) {
  const std::regex pattern(R"((\d{1,9})x(\d{1,9})x(\d{1,9}))");
  std::smatch match;
  if (!std::regex_match(text, match, pattern))
    throw std::runtime_error("size '" + text + "' is not of the form IxJxK (e.g. 512x512x1200)");
  const glm::ivec3 size(std::stoi(match[1]), std::stoi(match[2]), std::stoi(match[3]));
  if (glm::any(glm::lessThan(size, glm::ivec3(8))) || glm::any(glm::greaterThan(size, glm::ivec3(4096))))
    throw std::runtime_error("size '" + text + "': each axis must be 8..4096 voxels");
  return size;
}

PhantomStyle parseStyle(const std::string& name) {
  if (const auto style = parsePhantomStyle(name)) return *style;
  throw std::runtime_error("phantom style '" + name + "' is not realistic, portal-venous or simple");
}

}  // namespace angio
