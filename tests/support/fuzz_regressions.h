#pragma once
// Replays the inputs the fuzz targets once failed on (tests/data/fuzz-regressions/<target>/) through
// the same reader call (tests/fuzz/reader_inputs.h): each must parse or throw an std::exception
// with a one-line message naming the input, and warn in one line each. Inputs named "unfixed-..."
// are findings in code that is not the readers' own, kept for whoever fixes it: they are skipped
// (listed in the skip message), and scripts/fuzz.sh leaves them out of its seeds.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/fuzz/reader_inputs.h"

namespace angio::test_support {

// Replays every saved input of `targets`; returns the unfixed ones it skipped.
inline std::vector<std::string> replayFuzzRegressions(std::span<const fuzz::ReaderTarget> targets,
                                                      const std::filesystem::path& scratch) {
  namespace fs = std::filesystem;
  std::vector<std::string> unfixed;
  for (const fuzz::ReaderTarget& target : targets) {
    const fs::path folder = fs::path(ANGIORAY_TEST_DATA) / "fuzz-regressions" / target.name;
    if (!fs::is_directory(folder)) continue;
    std::vector<fs::path> inputs;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
      inputs.push_back(entry.path());
    std::sort(inputs.begin(), inputs.end());
    for (const fs::path& file : inputs) {
      const std::string name = std::string(target.name) + "/" + file.filename().string();
      if (file.filename().string().starts_with("unfixed-")) {
        unfixed.push_back(name);
        continue;
      }
      std::ifstream in(file, std::ios::binary);
      fuzz::FuzzInput input{{std::istreambuf_iterator<char>(in), {}}, scratch, {}, {}};
      EXPECT_EQ(fuzz::readerProblem(target, input), "") << name;
    }
  }
  return unfixed;
}

inline std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace angio::test_support
