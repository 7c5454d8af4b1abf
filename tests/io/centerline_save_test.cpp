// Centerline writers: saving in each format and loading again gives the same model (names, points,
// radii to the last bit), failed saves leave the target as it was, and the written files carry
// what Slicer and VTK look for.
#include "io/centerline_file.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <sys/fsuid.h>
#include <unistd.h>

#include "io/centerline_csv.h"
#include "io/centerline_markups.h"
#include "io/centerline_vtp.h"
#include "io/input_error.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

namespace fs = std::filesystem;
using test_support::expectInputError;
using test_support::fileBytes;

// --- Fixtures -----------------------------------------------------------------------------------

// A traced path: positions and radii computed in float, as a tracer stores them, so a format
// that keeps fewer than 9 significant digits would change them.
CenterlinePath tracedPath(const std::string& name, float x0, std::size_t count) {
  CenterlinePath path{name, {}};
  for (std::size_t n = 0; n < count; ++n) {
    const float t = 0.37f * float(n);
    path.points.push_back(
        {{x0 + 9.7f * std::cos(t), -316.4061f + 0.8789f * float(n), 24.3194f + std::sin(t)},
         10.3651f - 0.0271f * float(n)});
  }
  return path;
}

// Names a format could mangle (a separator, quotes, a line break, spaces at the ends, UTF-8), and
// doubles no short decimal holds.
Centerlines awkwardCenterlines() {
  Centerlines centerlines;
  centerlines.paths = {tracedPath("trunk, left \"iliac\"", -218.4904f, 40),
                       tracedPath("Aorta → A. iliaca dextra (右)", -150.25f, 25),
                       tracedPath("  two\nlines  ", 0.0f, 3)};
  centerlines.paths[2].points.push_back({{1.0 / 3.0, 0.1 + 0.2, 1e21}, 1e-7});
  centerlines.paths[2].points.push_back({{-1234567.890123456789, 5e-300, 7.0}, 2.0 / 3.0});
  return centerlines;
}

// Same paths, names and points, bit for bit (the source is where each was read from).
void expectSameModel(const Centerlines& loaded, const Centerlines& saved) {
  EXPECT_EQ(loaded.frame, CenterlineFrame::physical);
  ASSERT_EQ(loaded.paths.size(), saved.paths.size());
  for (std::size_t p = 0; p < saved.paths.size(); ++p) {
    EXPECT_EQ(loaded.paths[p].name, saved.paths[p].name) << "path " << p;
    ASSERT_EQ(loaded.paths[p].points.size(), saved.paths[p].points.size()) << "path " << p;
    for (std::size_t n = 0; n < saved.paths[p].points.size(); ++n) {
      const CenterlinePoint& a = loaded.paths[p].points[n];
      const CenterlinePoint& b = saved.paths[p].points[n];
      EXPECT_EQ(a.positionMm.x, b.positionMm.x) << "path " << p << " point " << n;
      EXPECT_EQ(a.positionMm.y, b.positionMm.y) << "path " << p << " point " << n;
      EXPECT_EQ(a.positionMm.z, b.positionMm.z) << "path " << p << " point " << n;
      EXPECT_EQ(a.radiusMm, b.radiusMm) << "path " << p << " point " << n;
    }
  }
}

Centerlines loadWithoutWarnings(const fs::path& file) {
  std::vector<std::string> warnings;
  CenterlineLoadOptions options;
  options.warn = [&](const std::string& warning) { warnings.push_back(warning); };
  const Centerlines loaded = loadCenterlines(file, options);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  return loaded;
}

// Root (as CI runs the tests) may write into any folder; while this lives, a root process checks
// file permissions as "nobody" does, so a read-only folder is read-only here too. setfsuid acts on
// the calling thread, the one the writers run on.
class AsOrdinaryUser {
 public:
  AsOrdinaryUser() : previousFsuid_(::geteuid() == 0 ? ::setfsuid(65534) : -1) {}
  ~AsOrdinaryUser() {
    if (previousFsuid_ >= 0) ::setfsuid(uid_t(previousFsuid_));
  }
  AsOrdinaryUser(const AsOrdinaryUser&) = delete;
  AsOrdinaryUser& operator=(const AsOrdinaryUser&) = delete;

 private:
  int previousFsuid_;
};

const std::string kUserData = "the user's own centerlines\n";

// --- Every format -------------------------------------------------------------------------------

class CenterlineSave : public test_support::TempFolderTest,
                       public ::testing::WithParamInterface<std::string> {
 protected:
  fs::path target() const { return dir_ / ("centerlines" + GetParam()); }
};

TEST_P(CenterlineSave, LoadingGivesBackTheSameModelBitForBit) {
  const Centerlines saved = awkwardCenterlines();
  saveCenterlines(saved, target());
  const Centerlines loaded = loadWithoutWarnings(target());
  EXPECT_EQ(loaded.source, target().string());
  expectSameModel(loaded, saved);
  EXPECT_EQ(filesInDir(), std::vector<std::string>{target().filename().string()});  // no temporary
}

TEST_P(CenterlineSave, UnnamedPathsComeBackNamedByTheirIndex) {
  Centerlines saved;
  saved.paths = {tracedPath("", 1.0f, 4), tracedPath("left", 2.0f, 3), tracedPath("", 3.0f, 2)};
  saveCenterlines(saved, target());
  const Centerlines loaded = loadWithoutWarnings(target());
  saved.paths[0].name = "0";
  saved.paths[2].name = "2";
  expectSameModel(loaded, saved);
}

TEST_P(CenterlineSave, ReplacesAnExistingFileWhole) {
  std::ofstream(target(), std::ios::binary) << std::string(100000, 'x');
  const Centerlines saved = awkwardCenterlines();
  saveCenterlines(saved, target());
  expectSameModel(loadWithoutWarnings(target()), saved);
}

TEST_P(CenterlineSave, MissingFolderIsAnInputErrorNamingTheFile) {
  const fs::path file = dir_ / "no-such-folder" / ("centerlines" + GetParam());
  expectInputError([&] { saveCenterlines(awkwardCenterlines(), file); }, file,
                   "cannot open for writing");
  EXPECT_TRUE(filesInDir().empty());
}

TEST_P(CenterlineSave, ReadOnlyFolderIsAnInputErrorAndTheExistingFileStaysByteIdentical) {
  const fs::path folder = dir_ / "read-only";
  fs::create_directory(folder);
  const fs::path file = folder / ("centerlines" + GetParam());
  std::ofstream(file, std::ios::binary) << kUserData;
  fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                              fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  {
    const AsOrdinaryUser ordinaryUser;
    expectInputError([&] { saveCenterlines(awkwardCenterlines(), file); }, file,
                     "cannot open for writing");
  }
  fs::permissions(folder, fs::perms::owner_all, fs::perm_options::add);
  EXPECT_EQ(fileBytes(file), kUserData);
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 1);
}

TEST_P(CenterlineSave, AFolderOfTheTargetsNameIsAnInputErrorAndIsLeftAlone) {
  // The temporary file is written, the rename over the folder fails.
  fs::create_directory(target());
  std::ofstream(target() / "inside.txt") << kUserData;
  expectInputError([&] { saveCenterlines(awkwardCenterlines(), target()); }, target(), "cannot write");
  EXPECT_EQ(fileBytes(target() / "inside.txt"), kUserData);
  EXPECT_EQ(filesInDir(), std::vector<std::string>{target().filename().string()});
}

TEST_P(CenterlineSave, VolumeFrameCenterlinesAreALogicErrorAndTheFileStaysAsItWas) {
  std::ofstream(target(), std::ios::binary) << kUserData;
  Centerlines framed = awkwardCenterlines();
  framed.frame = CenterlineFrame::volume;
  EXPECT_THROW(saveCenterlines(framed, target()), std::logic_error);
  EXPECT_EQ(fileBytes(target()), kUserData);
  EXPECT_EQ(filesInDir(), std::vector<std::string>{target().filename().string()});
}

// The vmtk file written by VTK 9.1, through each format and back.
TEST_P(CenterlineSave, SharedAortaCenterlinesSurviveTheFormat) {
  const Centerlines aorta =
      loadWithoutWarnings(fs::path(ANGIORAY_SHARED_DATA) / "aorta-centerlines.vtp");
  ASSERT_EQ(aorta.paths.size(), 2u);
  saveCenterlines(aorta, target());
  expectSameModel(loadWithoutWarnings(target()), aorta);
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, CenterlineSave,
                         ::testing::Values(".mrk.json", ".json", ".vtp", ".csv", ".CSV"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name;
                           for (char c : info.param) name += std::isalnum(c) ? c : '_';
                           return name + std::to_string(info.index);
                         });

using CenterlineSaveChoice = test_support::TempFolderTest;

TEST_F(CenterlineSaveChoice, UnknownExtensionIsAnInputErrorAndWritesNothing) {
  for (const std::string name : {"centerlines.txt", "centerlines.vtk", "centerlines"}) {
    expectInputError([&] { saveCenterlines(awkwardCenterlines(), dir_ / name); }, dir_ / name,
                     "unknown centerline format (use .mrk.json, .vtp or .csv)");
  }
  EXPECT_TRUE(filesInDir().empty());
}

// --- What other programs read -------------------------------------------------------------------

using Json = nlohmann::json;

// What Slicer's markups JSON reader needs (vtkMRMLMarkupsJsonStorageNode): an "@schema" it accepts,
// then per curve the fields SlicerVMTK's centerline curves have.
TEST_F(CenterlineSaveChoice, MarkupsFileHasTheFieldsSlicerReads) {
  const fs::path file = dir_ / "centerlines.mrk.json";
  const Centerlines saved = awkwardCenterlines();
  writeCenterlinesMarkups(saved, file);
  const Json json = Json::parse(fileBytes(file));
  // Slicer accepts any schema version 1.x.y by this pattern.
  EXPECT_TRUE(std::regex_match(json.at("@schema").get<std::string>(),
                               std::regex(".*markups-schema-v1\\.[0-9]+\\.[0-9]+\\.json#*")));
  ASSERT_EQ(json.at("markups").size(), saved.paths.size());
  for (std::size_t p = 0; p < saved.paths.size(); ++p) {
    const Json& markup = json["markups"][p];
    EXPECT_EQ(markup.at("type"), "Curve");
    EXPECT_EQ(markup.at("name"), saved.paths[p].name);
    EXPECT_EQ(markup.at("coordinateSystem"), "LPS");
    EXPECT_EQ(markup.at("coordinateUnits"), "mm");
    const Json& points = markup.at("controlPoints");
    ASSERT_EQ(points.size(), saved.paths[p].points.size());
    for (std::size_t n = 0; n < points.size(); ++n) {
      EXPECT_EQ(points[n].at("id"), std::to_string(n + 1));
      EXPECT_TRUE(points[n].at("label").is_string());
      EXPECT_EQ(points[n].at("position").size(), 3u);
      EXPECT_EQ(points[n].at("orientation").size(), 9u);
      EXPECT_EQ(points[n].at("positionStatus"), "defined");
      for (const char* flag : {"selected", "locked", "visibility"})
        EXPECT_TRUE(points[n].at(flag).is_boolean());
    }
    const Json& radius = markup.at("measurements").at(0);
    EXPECT_EQ(radius.at("name"), "Radius");
    EXPECT_EQ(radius.at("controlPointValues").size(), points.size());
  }
}

// One point and one radius per point of each path, one line cell per path, the names in CellData,
// in ascii; read back by this reader after the ascii String format VTK writes (tested in
// centerline_loader_test), so here: the layout VTK's reader needs.
TEST_F(CenterlineSaveChoice, VtpFileIsAsciiPolyDataOfOneLinePerPath) {
  const fs::path file = dir_ / "centerlines.vtp";
  const Centerlines saved = awkwardCenterlines();
  writeCenterlinesVtp(saved, file);
  const std::string text = fileBytes(file);
  EXPECT_NE(text.find("<VTKFile type=\"PolyData\" version=\"0.1\""), std::string::npos);
  EXPECT_NE(text.find("NumberOfPoints=\"70\" NumberOfVerts=\"0\" NumberOfLines=\"3\""),
            std::string::npos);
  EXPECT_NE(
      text.find("<DataArray type=\"Float64\" Name=\"MaximumInscribedSphereRadius\" format=\"ascii\">"),
      std::string::npos);
  EXPECT_NE(text.find("<DataArray type=\"String\" Name=\"CenterlineName\" NumberOfTuples=\"3\" "
                      "format=\"ascii\">"),
            std::string::npos);
  EXPECT_NE(text.find("          40 65 70\n"), std::string::npos);  // end offsets of the 3 cells
  EXPECT_EQ(text.find("format=\"binary\""), std::string::npos);
}

// RFC 4180: a field with a comma, quote or line break is quoted, quotes doubled.
TEST_F(CenterlineSaveChoice, CsvQuotesNamesThatNeedIt) {
  const fs::path file = dir_ / "centerlines.csv";
  Centerlines saved;
  saved.paths = {{"plain", {{{1, 2, 3}, 4}}},
                 {"a,b", {{{1, 2, 3}, 4}}},
                 {"say \"hi\"", {{{1, 2, 3}, 4}}},
                 {"", {{{0.5, -0.25, 1e21}, 0.1}}}};
  writeCenterlinesCsv(saved, file);
  EXPECT_EQ(fileBytes(file),
            "path,x_mm,y_mm,z_mm,radius_mm\n"
            "plain,1,2,3,4\n"
            "\"a,b\",1,2,3,4\n"
            "\"say \"\"hi\"\"\",1,2,3,4\n"
            "3,0.5,-0.25,1e+21,0.1\n");
}

TEST_F(CenterlineSaveChoice, CsvRefusesPathsThatWouldMerge) {
  const fs::path file = dir_ / "centerlines.csv";
  std::ofstream(file, std::ios::binary) << kUserData;
  Centerlines sameNames;
  sameNames.paths = {tracedPath("left", 1.0f, 2), tracedPath("right", 1.0f, 2),
                     tracedPath("left", 1.0f, 2)};
  expectInputError([&] { writeCenterlinesCsv(sameNames, file); }, file,
                   "paths 0 and 2 would both be written as path 'left'");
  Centerlines nameIsAnIndex;
  nameIsAnIndex.paths = {tracedPath("1", 1.0f, 2), tracedPath("", 1.0f, 2)};
  expectInputError([&] { writeCenterlinesCsv(nameIsAnIndex, file); }, file,
                   "paths 0 and 1 would both be written as path '1'");
  EXPECT_EQ(fileBytes(file), kUserData);
}

}  // namespace
}  // namespace angio
