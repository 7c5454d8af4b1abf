#pragma once
// Broken-file tests: a good file's text with one piece changed.
#include <string>

#include <gtest/gtest.h>

namespace angio::test_support {

// `text` with the first `from` replaced by `to` (a failure if `from` is not there).
inline std::string replacedOnce(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

}  // namespace angio::test_support
