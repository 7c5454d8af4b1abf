// Parsing JSON text for every reader: the nesting depth is counted outside strings, a text nested
// deeper than kMaxJsonDepth is refused before parsing (200,000 levels would exhaust the stack of
// whatever walks the value), and bad JSON is one line naming the file and the byte.
#include "io/json_text.h"

#include <gtest/gtest.h>

#include "io/input_error.h"

namespace angio {
namespace {

std::string errorOf(const std::string& text) {
  try {
    parseJsonText(text, "/data/t.json");
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(JsonText, DepthCountsArraysAndObjectsOutsideStrings) {
  EXPECT_EQ(jsonNestingDepth("1"), 0);
  EXPECT_EQ(jsonNestingDepth(R"({"a": [1, {"b": []}], "c": {}})"), 4);
  EXPECT_EQ(jsonNestingDepth(R"(["[[[", "\"{{", "\\"])"), 1);  // brackets in strings, escapes
}

TEST(JsonText, ATextNestedPastTheLimitIsRefusedNamingTheFile) {
  const std::string deep = std::string(200000, '[') + std::string(200000, ']');
  const std::string message = errorOf(deep);
  EXPECT_NE(message.find("/data/t.json"), std::string::npos) << message;
  EXPECT_NE(message.find("nested 200000 levels deep (at most 100)"), std::string::npos) << message;
  // At the limit it parses.
  const std::string atLimit = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
  EXPECT_EQ(errorOf(atLimit), "");
  EXPECT_EQ(jsonNestingDepth(atLimit), kMaxJsonDepth);
}

TEST(JsonText, BadJsonIsOneLineWithTheByteAndWithoutTheBytesRead) {
  const std::string message = errorOf(std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_NE(message.find("/data/t.json: not valid JSON at byte 1"), std::string::npos) << message;
  EXPECT_EQ(message.find("last read"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_NE(errorOf(R"({"a": 1e999})").find("number overflow"), std::string::npos);
}

}  // namespace
}  // namespace angio
