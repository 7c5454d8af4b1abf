// The bad-input catalogue: every case is a command line with one bad value (a flag's number that
// is NaN, infinite, out of range or malformed, a value a renderer cannot finish, a file no reader
// should walk). Each must end
// with a non-zero exit, no signal, within a time bound, one line on stdout/stderr that names the
// flag (or file) and the problem, and an output file that existed before left byte for byte as it
// was.
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/run_angioray.h"

namespace angio {
namespace {

namespace fs = std::filesystem;

constexpr int kTimeBoundSeconds = 60;

struct BadInput {
  // After the binary; {dir} is the test's folder, {aorta} the shared CTA, {cl} its centerlines.
  const char* arguments;
  const char* named;           // the flag or file the message must name
  const char* problem;         // a word of the problem the message must say
  const char* file = nullptr;  // written to {dir}/FILE first: `text` with {deep} replaced by
  const char* text = nullptr;  // ... an array nested 200,000 levels deep
};

void PrintTo(const BadInput& input, std::ostream* out) { *out << input.arguments; }

// The command lines with one bad value each, by subcommand.
constexpr BadInput kCatalogue[] = {
    // render: the view and the sampling.
    {"render {aorta} --out {dir}/out.png --angle nan", "--angle", "finite"},
    {"render {aorta} --out {dir}/out.png --angle inf", "--angle", "finite"},
    {"render {aorta} --out {dir}/out.png --angle -inf", "--angle", "finite"},
    {"render {aorta} --out {dir}/out.png --angle 12deg", "--angle", "12deg"},
    {"render {aorta} --out {dir}/out.png --isd nan", "--isd", "finite"},
    {"render {aorta} --out {dir}/out.png --isd 0", "--isd", ">="},
    {"render {aorta} --out {dir}/out.png --isd -1", "--isd", ">="},
    {"render {aorta} --out {dir}/out.png --isd 1e-9", "--isd", ">="},
    {"render {aorta} --out {dir}/out.png --isd 0.001", "out.png", "too large"},
    {"render {aorta} --out {dir}/out.png --osd nan", "--osd", "finite"},
    {"render {aorta} --out {dir}/out.png --osd 0", "--osd", ">="},
    {"render {aorta} --out {dir}/out.png --osd 1e-9", "--osd", ">="},
    {"render {aorta} --out {dir}/out.png --osd inf", "--osd", "finite"},
    {"render {aorta} --out {dir}/out.png --ert nan", "--ert", "finite"},
    {"render {aorta} --out {dir}/out.png --ert 5", "--ert", "[0, 1]"},
    {"render {aorta} --out {dir}/out.png --ert -0.5", "--ert", "[0, 1]"},
    {"render {aorta} --out {dir}/out.png --ka nan", "--ka", "finite"},
    {"render {aorta} --out {dir}/out.png --ka 11", "--ka", "[0, 10]"},
    {"render {aorta} --out {dir}/out.png --kd inf", "--kd", "finite"},
    {"render {aorta} --out {dir}/out.png --kd -1", "--kd", "[0, 10]"},
    {"render {aorta} --out {dir}/out.png --mip --window 0", "--window", "> 0"},
    {"render {aorta} --out {dir}/out.png --mip --window nan", "--window", "finite"},
    {"render {aorta} --out {dir}/out.png --mip --level nan", "--level", "finite"},
    {"render {aorta} --out {dir}/out.png --mip --level -inf", "--level", "finite"},
    {"render {aorta} --out {dir}/out.png --axis x", "--axis", "x"},
    {"render {aorta} --out {dir}/out.png --filter cubic", "--filter", "cubic"},
    {"render {aorta} --out {dir}/out.png --quality ultra", "--quality", "ultra"},
    {"render {aorta} --out {dir}/out.png --shading maybe", "--shading", "maybe"},
    // render: the image window, crop, clip plane and slab (comma lists).
    {"render {aorta} --out {dir}/out.png --image-window nan,1,2,3", "--image-window", "nan"},
    {"render {aorta} --out {dir}/out.png --image-window 1,2", "--image-window", "1,2"},
    {"render {aorta} --out {dir}/out.png --image-window 5,1,0,1", "image window", "left < right"},
    {"render {aorta} --out {dir}/out.png --crop 0,0,0,nan,10,10", "--crop", "nan"},
    {"render {aorta} --out {dir}/out.png --crop 0,0,0", "--crop", "0,0,0"},
    {"render {aorta} --out {dir}/out.png --clip 0,0,0,0,0,inf", "--clip", "inf"},
    {"render {aorta} --out {dir}/out.png --slab 0,nan", "--slab", "nan"},
    // render: VesselGlyph numbers.
    {"render {aorta} --out {dir}/out.png --transition nan", "--transition", "finite"},
    {"render {aorta} --out {dir}/out.png --transition -2", "--transition", ">= 0"},
    {"render {aorta} --out {dir}/out.png --cpr-window 0", "--cpr-window", "> 0"},
    {"render {aorta} --out {dir}/out.png --cpr-level nan", "--cpr-level", "finite"},
    // cpr.
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --width nan", "--width", "finite"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --width 0", "--width", "> 0"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --pixel inf", "--pixel", "finite"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --pixel -0.5", "--pixel", "> 0"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --window nan --level 100", "--window",
     "finite"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --window 100 --level inf", "--level", "finite"},
    {"cpr {aorta} --centerlines {cl} --out {dir}/out.png --bench-length nan", "--bench-length",
     "finite"},
    // gui (parsed before any window opens).
    {"gui {aorta} --headless --timeout nan", "--timeout", "finite"},
    {"gui {aorta} --headless --timeout 0", "--timeout", "> 0"},
    {"gui {aorta} --quit-after -1", "--quit-after", ">= 0"},
    {"gui {aorta} --motion-budget nan", "--motion-budget", "finite"},
    {"gui {aorta} --motion-budget 5000", "--motion-budget", "[0, 1000]"},
    // JSON files of every kind nested past any of ours (a stack overflow before).
    {"render {aorta} --out {dir}/out.png --tf {dir}/deep.json", "deep.json", "nested", "deep.json",
     R"({"name": "t", "points": [{"hu": {deep}, "color": [0, 0, 0], "opacity": 0}]})"},
    {"render --params {dir}/deep.json --out {dir}/out.png", "deep.json", "nested", "deep.json",
     R"({"angioray_render_sidecar": 1, "view": {"axis": {deep}}})"},
    {"render {aorta} --out {dir}/out.png --centerlines {dir}/deep.mrk.json --vg-focus circle:radius=3",
     "deep.mrk.json", "nested", "deep.mrk.json",
     R"({"markups": [{"type": "Curve", "controlPoints": [{"position": {deep}}]}]})"},
    {"gui {aorta} --headless --timeout 5 --session {dir}/deep.json", "deep.json", "nested", "deep.json",
     R"({"view": {"zoom": {deep}}})"},
    {"gui {aorta} --headless --timeout 5 --script {dir}/deep.json", "deep.json", "nested", "deep.json",
     R"([{"click": {deep}}])"},
};

struct Outcome {
  int exitCode = -1;  // -1: ended by a signal
  std::string output;
  double seconds = 0;
};

// Runs the binary under `timeout`, which kills it (a signal, so a failed case) after the bound.
Outcome runBounded(const std::string& arguments) {
  const std::string command = "timeout --signal=KILL " + std::to_string(kTimeBoundSeconds) + " " +
                              ANGIORAY_BINARY + " " + arguments + " 2>&1";
  const auto start = std::chrono::steady_clock::now();
  Outcome outcome;
  FILE* pipe = popen(command.c_str(), "r");
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) outcome.output += buffer.data();
  const int status = pclose(pipe);
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The shell reports a child's signal as 128 + its number.
  if (WIFEXITED(status) && WEXITSTATUS(status) < 128) outcome.exitCode = WEXITSTATUS(status);
  return outcome;
}

std::string replaced(std::string text, const std::string& what, const std::string& with) {
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + with.size()))
    text.replace(at, what.size(), with);
  return text;
}

std::string bytesOf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
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
  fs::path dir_;
};

TEST_P(BadInputCatalogue, EndsWithOneLineNamingTheFlagAndLeavesTheOutputAlone) {
  const BadInput& input = GetParam();
  const std::string data = ANGIORAY_SHARED_DATA;
  std::string arguments = replaced(input.arguments, "{dir}", dir_.string());
  arguments = replaced(replaced(arguments, "{aorta}", data + "/aorta.mha"), "{cl}",
                       data + "/aorta-centerlines.csv");
  const std::string before = "an export the user made earlier";
  std::ofstream(dir_ / "out.png", std::ios::binary) << before;
  std::ofstream(dir_ / "out.png.json", std::ios::binary) << before;
  if (input.file)
    std::ofstream(dir_ / input.file)
        << replaced(input.text, "{deep}", std::string(200000, '[') + std::string(200000, ']'));

  const Outcome outcome = runBounded(arguments);
  ASSERT_GE(outcome.exitCode, 1) << arguments << " (signal or success)\n" << outcome.output;
  EXPECT_LT(outcome.seconds, kTimeBoundSeconds) << arguments;
  EXPECT_EQ(std::count(outcome.output.begin(), outcome.output.end(), '\n'), 1) << arguments << "\n"
                                                                               << outcome.output;
  EXPECT_NE(outcome.output.find(input.named), std::string::npos) << arguments << "\n" << outcome.output;
  EXPECT_NE(outcome.output.find(input.problem), std::string::npos) << arguments << "\n"
                                                                   << outcome.output;
  EXPECT_EQ(bytesOf(dir_ / "out.png"), before) << arguments;
  EXPECT_EQ(bytesOf(dir_ / "out.png.json"), before) << arguments;
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), input.file ? 3 : 2)
      << arguments << ": nothing else written";
}

std::string caseName(const ::testing::TestParamInfo<BadInput>& info) {
  std::string name = std::to_string(info.index) + "_";
  for (const char* c = info.param.arguments; *c; ++c)
    if (std::isalnum(static_cast<unsigned char>(*c)) && name.size() < 60) name += *c;
  return name;
}

INSTANTIATE_TEST_SUITE_P(CommandLine, BadInputCatalogue, ::testing::ValuesIn(kCatalogue), caseName);

}  // namespace
}  // namespace angio
