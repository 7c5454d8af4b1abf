#pragma once
// The one error type of io/: what went wrong with which file, as one line for the user; and the
// one way a warning about an input (a clipped path, an odd header) reaches the terminal.
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace angio {

class InputError : public std::runtime_error {
 public:
  InputError(const std::filesystem::path& file, const std::string& problem)
      : std::runtime_error(file.string() + ": " + problem) {}
};

// "angioray: warning: TEXT" on stderr, one line.
inline void printWarning(const std::string& warning) {
  std::fprintf(stderr, "angioray: warning: %s\n", warning.c_str());
}

}  // namespace angio
