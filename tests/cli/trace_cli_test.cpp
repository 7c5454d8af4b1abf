// `angioray trace` on the real aorta: between the reference centerlines' ends it writes a path
// that lies on them, in each centerline format; bad points and unwritable outputs get one line
// naming the flag or the file, and an existing output stays as it was.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "io/centerline_file.h"
#include "io/volume_reader.h"
#include "tests/support/run_angioray.h"
#include "tests/support/temp_folder_test.h"
#include "vessel/centerline_comparison.h"

namespace angio {
namespace {

using test_support::runAngioray;

const std::string kData = ANGIORAY_SHARED_DATA;

std::string pointText(glm::dvec3 p) {
  char text[100];
  std::snprintf(text, sizeof text, "%.3f,%.3f,%.3f", p.x, p.y, p.z);
  return text;
}

int lineCount(const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); }

class TraceCli : public test_support::TempFolderTest {
 protected:
  void SetUp() override {
    TempFolderTest::SetUp();
    reference_ = loadCenterlines(kData + "/aorta-centerlines.csv");
    const CenterlinePath& path = reference_.paths.front();
    points_ = pointText(path.points.front().positionMm) + ";" + pointText(path.points.back().positionMm);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  Centerlines reference_;
  std::string points_;
};

TEST_F(TraceCli, TracesTheAortaBetweenTwoPointsInEveryFormat) {
  for (const std::string name : {"aorta.vtp", "aorta.mrk.json", "aorta.csv"}) {
    const auto run = runAngioray("trace " + kData + "/aorta.mha --points \"" + points_ + "\" --out " +
                                 file(name) + " --compare " + kData + "/aorta-centerlines.vtp");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("vs reference"), std::string::npos) << run.output;
    const Centerlines traced = loadCenterlines(file(name));
    ASSERT_EQ(traced.paths.size(), 1u) << name;
    // Both in the physical frame, as the files hold them.
    const CenterlineDeviation d = deviationFrom(traced.paths.front(), reference_.paths.front());
    EXPECT_LE(d.meanMm, 1.0) << name;
    EXPECT_GT(traced.paths.front().points.front().radiusMm, 5.0) << name;  // the aorta's radius
  }
}

TEST_F(TraceCli, BadPointsAndOutputsGetOneLineAndLeaveTheOutputAlone) {
  const std::string kept = "path,x_mm,y_mm,z_mm,radius_mm\n0,1,2,3,4\n";
  write("kept.csv", kept);
  const std::string volume = kData + "/aorta.mha";
  struct Case {
    std::string arguments, expected;
  };
  const std::vector<Case> cases{
      {"--points \"1,2\"", "--points: '1,2' is not three finite numbers"},
      {"--points \"1,2,nan;3,4,5\"", "--points: '1,2,nan' is not three finite numbers"},
      {"--points \"" + pointText(reference_.paths.front().points.front().positionMm) + "\"",
       "a path needs at least two points"},
      {"--points \"5000,0,0;" + pointText(reference_.paths.front().points.back().positionMm) + "\"",
       "point 1: the point lies outside the volume"},
      {"--voxels \"1,1,1;2,2,2\"", "point 1: no contrast-filled vessel"},
      {"", "give the points with either --points"},
  };
  for (const Case& c : cases) {
    const auto run = runAngioray("trace " + volume + " " + c.arguments + " --out " + file("kept.csv"));
    EXPECT_NE(run.exitCode, 0) << c.arguments;
    EXPECT_NE(run.output.find(c.expected), std::string::npos) << c.arguments << "\n" << run.output;
    EXPECT_EQ(lineCount(run.output), 1) << run.output;
    EXPECT_EQ(test_support::fileBytes(file("kept.csv")), kept) << c.arguments;
  }
  const auto unwritable = runAngioray("trace " + volume + " --points \"" + points_ + "\" --out " +
                                      file("missing/dir/a.vtp"));
  EXPECT_NE(unwritable.exitCode, 0);
  EXPECT_NE(unwritable.output.find("missing/dir/a.vtp"), std::string::npos) << unwritable.output;
  const auto unknown =
      runAngioray("trace " + volume + " --points \"" + points_ + "\" --out " + file("a.txt"));
  EXPECT_NE(unknown.exitCode, 0);
  EXPECT_EQ(test_support::fileBytes(file("kept.csv")), kept);
}

}  // namespace
}  // namespace angio
