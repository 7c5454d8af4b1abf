#pragma once
// One case of the bad-input catalogues (tests/cli/bad_input_*_test.cpp): a command line with one
// bad value or file. It must end with a non-zero exit, no signal, within a time bound, with one
// line of output that names the flag (or file) and the problem, and leave every file of its
// folder, outputs made earlier included, byte for byte as it was.
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/file_bytes.h"

namespace angio::test_support {

namespace fs = std::filesystem;

inline constexpr int kBadInputSeconds = 60;

struct BadInput {
  // After the binary; {dir} is the case's folder, {aorta} the shared CTA, {cl} its centerlines.
  const char* arguments;
  const char* named;           // the flag or file the message must name
  const char* problem;         // a phrase of the problem the message must say
  const char* file = nullptr;  // written to {dir}/FILE first: `text`, with {deep} replaced by an
  const char* text = nullptr;  // array nested 200,000 levels deep
  void (*prepare)(const fs::path& dir) = nullptr;  // or made by this
};

inline void PrintTo(const BadInput& input, std::ostream* out) { *out << input.arguments; }

inline std::string replaced(std::string text, const std::string& what, const std::string& with) {
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + with.size()))
    text.replace(at, what.size(), with);
  return text;
}

// Every file and folder under `dir` with its bytes ("<folder>" for folders).
inline std::map<fs::path, std::string> snapshot(const fs::path& dir) {
  std::map<fs::path, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    files[entry.path()] = entry.is_directory() ? "<folder>" : fileBytes(entry.path());
  return files;
}

struct BoundedRun {
  int exitCode = -1;  // -1: ended by a signal
  std::string output;
  double seconds = 0;
};

// The binary under test; ANGIORAY_CATALOGUE_BINARY runs the catalogue against another build (an
// earlier one, to count what it did with each case).
inline std::string binaryUnderTest() {
  const char* other = std::getenv("ANGIORAY_CATALOGUE_BINARY");
  return other && *other ? other : ANGIORAY_BINARY;
}

// Runs the binary under `timeout`, which kills it (a signal, so a failed case) after the bound.
inline BoundedRun runBounded(const std::string& arguments) {
  const std::string command = "timeout --signal=KILL " + std::to_string(kBadInputSeconds) + " " +
                              binaryUnderTest() + " " + arguments + " 2>&1";
  const auto start = std::chrono::steady_clock::now();
  BoundedRun run;
  FILE* pipe = popen(command.c_str(), "r");
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) run.output += buffer.data();
  const int status = pclose(pipe);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The shell reports a child's signal as 128 + its number.
  if (WIFEXITED(status) && WEXITSTATUS(status) < 128) run.exitCode = WEXITSTATUS(status);
  return run;
}

// What a run did with its bad input, as the catalogue counts it: "hung" (killed at the bound),
// "crashed" (a signal), "accepted" (exit 0), "damaged" (refused, but a file of the folder
// changed), "several lines", "unclear" (one line not naming the flag or file and the problem),
// "clean".
inline std::string outcomeOf(const BadInput& input, const BoundedRun& run, bool unchanged) {
  if (run.seconds >= kBadInputSeconds - 1) return "hung";
  if (run.exitCode < 0) return "crashed";
  if (run.exitCode == 0) return "accepted";
  if (!unchanged) return "damaged";
  if (std::count(run.output.begin(), run.output.end(), '\n') != 1) return "several lines";
  const bool named = run.output.find(input.named) != std::string::npos &&
                     run.output.find(input.problem) != std::string::npos;
  return named ? "clean" : "unclear";
}

class BadInputCatalogue : public ::testing::TestWithParam<BadInput> {
 protected:
  void SetUp() override {
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(name.begin(), name.end(), '/', '-');
    dir_ = fs::temp_directory_path() / ("angioray-bad-input-" + name);
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void expectCleanRefusal(const BadInput& input) const {
    const std::string data = ANGIORAY_SHARED_DATA;
    std::string arguments = replaced(input.arguments, "{dir}", dir_.string());
    arguments = replaced(replaced(arguments, "{aorta}", data + "/aorta.mha"), "{cl}",
                         data + "/aorta-centerlines.csv");
    // Outputs the user made earlier; a case may replace them (a folder where the sidecar goes).
    std::ofstream(dir_ / "out.png", std::ios::binary) << "an export the user made earlier";
    std::ofstream(dir_ / "out.png.json", std::ios::binary) << "its sidecar";
    if (input.file)
      std::ofstream(dir_ / input.file, std::ios::binary)
          << replaced(input.text, "{deep}", std::string(200000, '[') + std::string(200000, ']'));
    if (input.prepare) input.prepare(dir_);
    const auto before = snapshot(dir_);

    const BoundedRun run = runBounded(arguments);
    const bool unchanged = snapshot(dir_) == before;
    std::printf("outcome: %s\n", outcomeOf(input, run, unchanged).c_str());
    ASSERT_GE(run.exitCode, 1) << arguments << " (signal or success)\n" << run.output;
    EXPECT_LT(run.seconds, kBadInputSeconds) << arguments;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << arguments << "\n"
                                                                         << run.output;
    EXPECT_NE(run.output.find(input.named), std::string::npos) << arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(input.problem), std::string::npos) << arguments << "\n" << run.output;
    EXPECT_TRUE(unchanged) << arguments << ": a file was changed, added or removed";
  }

  fs::path dir_;
};

// "3_renderaortaoutdiroutpngangle..." from the case's arguments.
inline std::string caseName(const ::testing::TestParamInfo<BadInput>& info) {
  std::string name = std::to_string(info.index) + "_";
  for (const char* c = info.param.arguments; *c; ++c)
    if (std::isalnum(static_cast<unsigned char>(*c)) && name.size() < 60) name += *c;
  return name;
}

}  // namespace angio::test_support
