// The readers' saved fuzz findings (tests/data/fuzz-regressions/<target>/), replayed through the
// same calls as the fuzz targets (tests/fuzz), and the bounds the .vtp reader and every centerline
// format keep against hostile files.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "io/centerline_file.h"
#include "io/input_error.h"
#include "tests/fuzz/reader_inputs.h"
#include "tests/support/fuzz_regressions.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

using FuzzRegression = test_support::TempFolderTest;

TEST_F(FuzzRegression, SavedInputsAreReadOrRefusedInOneLine) {
  const std::vector<std::string> unfixed =
      test_support::replayFuzzRegressions(fuzz::kIoReaderTargets, dir_);
  if (!unfixed.empty()) GTEST_SKIP() << "unfixed: " << test_support::joined(unfixed);
}

// The message of the InputError `read` throws, checked to be one line naming `file`.
template <class Read>
std::string refusal(const std::string& file, Read read) {
  try {
    read();
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(fuzz::messageProblem(message, file), "") << message;
    return message;
  }
  ADD_FAILURE() << file << " was read";
  return "";
}

std::string vtpPiece(const std::string& counts, const std::string& points,
                     const std::string& connectivity, const std::string& offsets,
                     const std::string& header = "") {
  return "<VTKFile type=\"PolyData\" byte_order=\"LittleEndian\"" + header + "><PolyData><Piece " +
         counts + "><Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">" +
         points +
         "</DataArray></Points><Lines>"
         "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" +
         connectivity + "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" +
         offsets + "</DataArray></Lines></Piece></PolyData></VTKFile>";
}

// A header may claim any count: it is held against the bytes the file has before anything is
// allocated for it, ascii or compressed.
TEST(FuzzRegressionVtp, HugeCountsAreRefusedBeforeAllocating) {
  const std::string ascii =
      vtpPiece("NumberOfPoints=\"1099511627776\" NumberOfLines=\"1\"", "0 0 0 1 1 1", "0 1", "2");
  EXPECT_NE(
      refusal("huge.vtp", [&] { parseCenterlinesVtp(ascii, "huge.vtp"); }).find("1099511627776 tuples"),
      std::string::npos);
  // zlib: one block said to inflate to 2^40 * 24 bytes from 16 compressed ones (UInt64 header words
  // 1, 2^40*24, 2^40*24, 16, base64 encoded).
  const std::string zlib =
      "<VTKFile type=\"PolyData\" header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\"><PolyData>"
      "<Piece NumberOfPoints=\"1099511627776\" NumberOfLines=\"0\"><Points><DataArray type=\"Float64\" "
      "NumberOfComponents=\"3\" "
      "format=\"binary\">AQAAAAAAAAAAAAAAABgAAAAAAAAAGAAAEAAAAAAAAAA=eJwDAAAAAAE="
      "</DataArray></Points></Piece></PolyData></VTKFile>";
  refusal("huge-zlib.vtp", [&] { parseCenterlinesVtp(zlib, "huge-zlib.vtp"); });
  const std::string lines =
      vtpPiece("NumberOfPoints=\"2\" NumberOfLines=\"18446744073709551615\"", "0 0 0 1 1 1", "0 1", "2");
  refusal("lines.vtp", [&] { parseCenterlinesVtp(lines, "lines.vtp"); });
}

// One point repeated 2e8 times (1.6 GB of Int64, a small file compressed) would take gigabytes and
// minutes: a line visits each point once, which the offsets already tell.
TEST(FuzzRegressionVtp, ConnectivityLongerThanItsPointsIsRefusedAtOnce) {
  const std::string repeated =
      vtpPiece("NumberOfPoints=\"1\" NumberOfLines=\"1\"", "0 0 0", "0 0 0", "200000000");
  const auto start = std::chrono::steady_clock::now();
  const std::string message =
      refusal("repeated.vtp", [&] { parseCenterlinesVtp(repeated, "repeated.vtp"); });
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  EXPECT_NE(message.find("200000000 connectivity entries for 1 points in 1 lines"), std::string::npos)
      << message;
}

// A path of one point has no direction: refused by every format, naming the file and the path.
TEST_F(FuzzRegression, SinglePointPathsAreRefusedInEveryFormat) {
  const std::string csv = "path,x_mm,y_mm,z_mm,radius_mm\naorta,0,0,0,1\naorta,0,0,5,1\nstub,1,2,3,1\n";
  const std::string vtp =
      vtpPiece("NumberOfPoints=\"3\" NumberOfLines=\"2\"", "0 0 0 0 0 5 1 2 3", "0 1 2", "2 3");
  const std::string markups =
      R"({"markups": [{"type": "Curve", "name": "aorta", "controlPoints": [{"position": [0, 0, 0]},)"
      R"( {"position": [0, 0, 5]}]}, {"type": "Curve", "name": "stub", "controlPoints": [{"position": [1, 2, 3]}]}]})";
  for (const auto& file : {std::pair{"single.csv", csv}, std::pair{"single.vtp", vtp},
                           std::pair{"single.mrk.json", markups}}) {
    const std::string name = file.first;
    const std::string message = refusal(name, [&] { loadCenterlines(write(name, file.second)); });
    EXPECT_NE(message.find("has a single point"), std::string::npos) << message;
    EXPECT_NE(message.find(name == "single.vtp" ? "'1' (number 2)" : "'stub' (number 2)"),
              std::string::npos)
        << message;
  }
}

// Path names are the file's: a line break in one is shown as \n, so messages stay one line.
TEST_F(FuzzRegression, PathNamesWithLineBreaksKeepMessagesOnOneLine) {
  const std::string csv = "path,x_mm,y_mm,z_mm,radius_mm\n\"two\nlines\",0,0,0,1\n";
  const std::string message = refusal("break.csv", [&] { loadCenterlines(write("break.csv", csv)); });
  EXPECT_NE(message.find("'two\\nlines'"), std::string::npos) << message;
}

}  // namespace
}  // namespace angio
