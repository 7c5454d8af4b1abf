#pragma once
// The io module's error contract, checked the same way by every io test: a failing call throws an
// InputError whose message is one line that names the file and says what is wrong with it.
#include <filesystem>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "io/input_error.h"

namespace angio::test_support {

// Expects `call` to throw an InputError whose message is one line, names `file` and contains
// `problem`. Returns the message, or nothing (after a failure) if `call` did not throw.
template <class Call>
std::optional<std::string> expectInputError(Call&& call, const std::filesystem::path& file,
                                            const std::string& problem) {
  try {
    call();
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << "wanted \"" << problem << "\" in " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << "no InputError for " << file;
  return std::nullopt;
}

}  // namespace angio::test_support
