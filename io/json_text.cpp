#include "io/json_text.h"

#include <algorithm>

#include "io/input_error.h"

namespace angio {

int jsonNestingDepth(const std::string& text) {
  int depth = 0, deepest = 0;
  bool inString = false, escaped = false;
  for (const char c : text) {
    if (inString) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') inString = false;
      continue;
    }
    if (c == '"') inString = true;
    else if (c == '[' || c == '{') deepest = std::max(deepest, ++depth);
    else if (c == ']' || c == '}') --depth;
  }
  return deepest;
}

nlohmann::json parseJsonText(const std::string& text, const std::filesystem::path& source) {
  using Json = nlohmann::json;
  if (const int depth = jsonNestingDepth(text); depth > kMaxJsonDepth)
    throw InputError(source, "JSON nested " + std::to_string(depth) + " levels deep (at most " +
                                 std::to_string(kMaxJsonDepth) + ")");
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& error) {
    // what() is "[json.exception.parse_error.101] parse error at line 1, column 2: <reason>;
    // last read: '<bytes>'": the bytes may be binary (an image given by mistake), so they go.
    std::string message = error.what();
    const auto reasonStart = message.find(": ");
    std::string reason = reasonStart == std::string::npos ? message : message.substr(reasonStart + 2);
    reason = reason.substr(0, reason.find("; last read"));
    throw InputError(source, "not valid JSON at byte " + std::to_string(error.byte) + ": " + reason);
  } catch (const Json::exception& error) {
    // E.g. out_of_range 406 "number overflow parsing '1e999'", which carries no position.
    const std::string message = error.what();
    throw InputError(source, "not valid JSON: " + message.substr(message.find(']') + 2));
  }
}

}  // namespace angio
