// Ground-truth centerline CSV: the reference file's format, written atomically.
#include "io/centerline_csv.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "io/input_error.h"
#include "tests/support/temp_folder_test.h"
#include "vessel/centerline.h"

namespace angio {
namespace {

namespace fs = std::filesystem;
using test_support::fileBytes;

class CenterlineCsvTest : public test_support::TempFolderTest {
 protected:
  // One path of one point at the origin, radius 1 mm.
  static Centerlines onePoint() {
    Centerlines centerlines;
    centerlines.paths = {{"a", {{{0, 0, 0}, 1}}}};
    return centerlines;
  }
};

// Numbers as the shortest text that reads back as the same double: no digits lost (a float
// widened to double keeps all of its), none padded.
TEST_F(CenterlineCsvTest, WritesOneRowPerPointWithThePathNameOrIndex) {
  Centerlines centerlines;
  centerlines.paths = {{"a", {{{1.0, -2.5, 3.25}, 10.0}, {{1.0, -2.5, 2.25}, 9.5}}},
                       {"", {{{-0.0004, 100.1234, -1199.5}, 1.5}}},
                       {"float", {{{double(-218.4904f), 0.1, -0.0}, double(10.3651f)}}}};
  const fs::path file = dir_ / "centerlines.csv";
  writeCenterlinesCsv(centerlines, file);
  EXPECT_EQ(fileBytes(file),
            "path,x_mm,y_mm,z_mm,radius_mm\n"
            "a,1,-2.5,3.25,10\n"
            "a,1,-2.5,2.25,9.5\n"
            "1,-0.0004,100.1234,-1199.5,1.5\n"
            "float,-218.4904022216797,0.1,0,10.365099906921387\n");
}

TEST_F(CenterlineCsvTest, HeaderMatchesTheSharedReferenceFile) {
  std::ifstream reference(std::string(ANGIORAY_SHARED_DATA) + "/aorta-centerlines.csv");
  std::string header;
  ASSERT_TRUE(std::getline(reference, header));
  const fs::path file = dir_ / "empty.csv";
  writeCenterlinesCsv({}, file);
  EXPECT_EQ(fileBytes(file), header + "\n");
}

TEST_F(CenterlineCsvTest, UnwritableTargetThrowsInputErrorAndLeavesNothing) {
  const fs::path file = dir_ / "missing-dir" / "centerlines.csv";
  try {
    writeCenterlinesCsv(onePoint(), file);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
  }
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(CenterlineCsvTest, ReplacesAnExistingFileWhole) {
  const fs::path file = dir_ / "centerlines.csv";
  std::ofstream(file) << "old content that is longer than the new one\n" << std::string(1000, 'x');
  writeCenterlinesCsv(onePoint(), file);
  EXPECT_EQ(fileBytes(file), "path,x_mm,y_mm,z_mm,radius_mm\na,0,0,0,1\n");
}

}  // namespace
}  // namespace angio
