#pragma once
// The one error type of io/: what went wrong with which file, as one line for the user.
#include <filesystem>
#include <stdexcept>
#include <string>

namespace angio {

class InputError : public std::runtime_error {
 public:
  InputError(const std::filesystem::path& file, const std::string& problem)
      : std::runtime_error(file.string() + ": " + problem) {}
};

}  // namespace angio
