// The workstation's Data, rotation-series and Session parts through the headless twin: a volume
// opened with the file browser replaces the phantom; a corrupt file keeps it and shows the error;
// sessions save, load and restore (also as the last session offered on start); the Export
// section's rotation series writes its files. XDG_CONFIG_HOME points into the test's folder.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>
#include <OpenImageIO/imagebuf.h>

#include "gui/file_browser.h"
#include "io/volume_reader.h"
#include "tests/support/dicom_series_writer.h"
#include "tests/support/run_angioray.h"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using angio::test_support::runAngioray;
using GuiRun = angio::test_support::ProgramRun;

// Tall enough for the whole side panel; the phantom started on differs from the opened volume.
const std::string kGui =
    "gui --headless --phantom-size 96x96x200 --phantom-style simple --size 1000x1400 --timeout 120";

Json readJson(const fs::path& path) {
  std::ifstream in(path);
  return Json::parse(in);
}

std::string centre(const Json& rect) {
  char text[64];
  std::snprintf(text, sizeof text, "[%.1f, %.1f]", (rect[0].get<float>() + rect[2].get<float>()) / 2,
                (rect[1].get<float>() + rect[3].get<float>()) / 2);
  return text;
}

std::vector<std::uint8_t> rgb8Of(const fs::path& png) {
  OIIO::ImageBuf image(png.string());
  EXPECT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::UINT8)) << png;
  const OIIO::ImageSpec& spec = image.spec();
  std::vector<std::uint8_t> pixels(std::size_t(spec.width) * spec.height * 3);
  image.get_pixels(OIIO::ROI(0, spec.width, 0, spec.height, 0, 1, 0, 3), OIIO::TypeDesc::UINT8,
                   pixels.data());
  return pixels;
}

class GuiData : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // Per process: ctest runs each test in its own process, in parallel.
    shared_ = fs::temp_directory_path() / ("angioray-gui-data-shared-" + std::to_string(::getpid()));
    fs::remove_all(shared_);
    fs::create_directories(shared_);
    volume_ = shared_ / "small.mha";
    const GuiRun run = runAngioray("phantom " + volume_.string() + " --size 64x64x128 --style simple");
    ASSERT_EQ(run.exitCode, 0) << run.output;
  }
  static void TearDownTestSuite() { fs::remove_all(shared_); }

  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("angioray-gui-data-" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "config");
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME")) savedXdg_ = xdg;
    setenv("XDG_CONFIG_HOME", (dir_ / "config").c_str(), 1);
  }
  void TearDown() override {
    if (savedXdg_) setenv("XDG_CONFIG_HOME", savedXdg_->c_str(), 1);
    else unsetenv("XDG_CONFIG_HOME");
    if (!HasFailure()) fs::remove_all(dir_);
  }

  std::string file(const std::string& name) const { return (dir_ / name).string(); }

  GuiRun runScript(const std::string& steps, const std::string& extra = "") {
    std::ofstream(dir_ / "script.json") << steps;
    return runAngioray(kGui + " --script " + file("script.json") + " --state-out " + file("end.json") +
                       extra);
  }

  // The start-up screen's state (its layout places the clicks).
  Json startup(const std::string& extra = "") {
    const GuiRun run = runAngioray(kGui + " --state-out " + file("startup.json") + extra);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return readJson(dir_ / "startup.json");
  }

  static fs::path shared_, volume_;
  fs::path dir_;
  std::optional<std::string> savedXdg_;
};

fs::path GuiData::shared_, GuiData::volume_;

// A DICOM series with its patient's tags: the banner shows who and what (over the image and in
// the Data section); its values (-300 .. 400 HU, no air) do not look like calibrated HU.
TEST_F(GuiData, ADicomSeriesShowsItsPatientBannerAndValuesWithoutAirAreFlagged) {
  const fs::path series = dir_ / "series";
  fs::create_directories(series);
  angio::test_support::writeDicomSeries(series, {0, 1, 2, 3, 4, 5, 6, 7},
                                        "1.2.826.0.1.3680043.2.1125.777.1", 3,
                                        {{"0010|0010", "DOE^JANE"},
                                         {"0010|0020", "PAT-0042"},
                                         {"0008|0020", "20240301"},
                                         {"0008|103e", "CTA Aorta"}});
  const GuiRun run = runAngioray(
      "gui " + series.string() + " --headless --size 1000x800 --timeout 120 --script " +
      [&] {
        std::ofstream(dir_ / "script.json")
            << R"([{"wait_level": "high"}, {"screenshot": ")" + file("banner.png") + R"("}])";
        return file("script.json");
      }() +
      " --state-out " + file("end.json"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json data = readJson(dir_ / "end.json")["runtime"]["data"];
  EXPECT_EQ(data["study"], Json({"DOE, JANE   ID PAT-0042", "2024-03-01   CTA Aorta   CT"}));
  EXPECT_EQ(data["hu_calibrated"], false);
}

TEST_F(GuiData, FileBrowserOpensAVolumeThatReplacesThePhantom) {
  const Json layout = startup()["runtime"]["layout"];
  const std::string steps = R"([
    {"click": )" + centre(layout["data_open"]) +
                            R"(}, {"wait_ms": 50},
    {"key": "Ctrl+A"}, {"text": ")" +
                            shared_.string() + R"("}, {"key": "Enter"}, {"wait_ms": 50},
    {"screenshot": ")" + file("browser.png") +
                            R"("},
    {"key": "Ctrl+A"}, {"text": "small.mha"}, {"key": "Enter"},
    {"wait_level": "high"}])";
  const GuiRun run = runScript(steps);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_TRUE(fs::exists(dir_ / "browser.png"));
  const Json end = readJson(dir_ / "end.json");
  const Json& data = end["runtime"]["data"];
  EXPECT_EQ(data["name"], volume_.string());
  EXPECT_EQ(data["dims"], Json({64, 64, 128}));
  EXPECT_EQ(data["description"], "MetaImage int16");
  EXPECT_EQ(data["orientation"], "LPS");
  EXPECT_FALSE(data["hu_range"].is_null());
  EXPECT_EQ(data["hu_calibrated"], true);  // the phantom holds air around the body
  EXPECT_EQ(data["load_error"], "");
  EXPECT_EQ(data["recent_files"], Json({volume_.string()}));
  EXPECT_EQ(end["state"]["dataset"], volume_.string());
  // The new volume is what is rendered: the high image of its own (smaller) extent.
  EXPECT_EQ(end["runtime"]["shown"]["level"], "high");
  EXPECT_LT(end["runtime"]["shown"]["width"].get<int>(), 200);
}

TEST_F(GuiData, TheArrowKeysDoNotTurnTheViewBehindTheOpenBrowser) {
  const Json layout = startup()["runtime"]["layout"];
  // The browser opens in the window's middle; a click on its list takes the keys from the path
  // field, so only the modal itself can keep them from the view.
  const GuiRun run = runScript(R"([{"click": )" + centre(layout["data_open"]) +
                               R"(}, {"wait_ms": 50}, {"click": [500, 700]}, {"key": "Left"},
                                    {"key": "Right"}, {"key": "Right"}, {"wait_ms": 50}])");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_DOUBLE_EQ(readJson(dir_ / "end.json")["state"]["view"]["angle_deg"].get<double>(), 0);
}

TEST_F(GuiData, ADatasetGivenOnTheCommandLineIsARecentFile) {
  const GuiRun run =
      runAngioray("gui " + volume_.string() + " --headless --size 1000x1400 --timeout 120 --state-out " +
                  file("end.json"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(readJson(dir_ / "end.json")["state"]["recent_files"], Json({volume_.string()}));
}

TEST_F(GuiData, FileBrowserListsFoldersFirstThenVolumeFilesSortedByName) {
  const fs::path folder = dir_ / "listing";
  for (const char* sub : {"beta", "Alpha", "series", ".hidden"}) fs::create_directories(folder / sub);
  for (const char* name :
       {"b.nii.gz", "A.MHA", "c.nrrd", "notes.txt", "d.nhdr", "e.mhd", "f.nii", ".x.mha"})
    std::ofstream(folder / name) << "x";
  std::ofstream slice(folder / "series" / "0001", std::ios::binary);  // DICOM: "DICM" at byte 128
  slice << std::string(128, '\0') << "DICM";
  slice.close();
  std::vector<std::string> names;
  for (const angio::BrowserEntry& entry : angio::listFolder(folder))
    names.push_back(entry.name + (entry.folder ? "/" : "") + (entry.dicomSeries ? " [DICOM]" : ""));
  EXPECT_EQ(names, (std::vector<std::string>{"Alpha/", "beta/", "series/ [DICOM]", "A.MHA", "b.nii.gz",
                                             "c.nrrd", "d.nhdr", "e.mhd", "f.nii"}));
  EXPECT_THROW(angio::listFolder(folder / "missing"), std::runtime_error);
}

// Each "..." field's browser lists the files it is for; the series folder's, folders only.
TEST_F(GuiData, FileBrowserListsWhatEachFieldIsFor) {
  const fs::path folder = dir_ / "mixed";
  fs::create_directories(folder / "views");
  for (const char* name : {"tf.json", "shot.png", "shot.TIF", "float.exr", "scan.mha", "c.vtp", "n.txt"})
    std::ofstream(folder / name) << "x";
  const auto listed = [&](angio::BrowserPurpose purpose) {
    std::vector<std::string> names;
    for (const angio::BrowserEntry& entry : angio::listFolder(folder, purpose))
      names.push_back(entry.name);
    return names;
  };
  using Names = std::vector<std::string>;
  using angio::BrowserPurpose;
  EXPECT_EQ(listed(BrowserPurpose::tfFile), (Names{"views", "tf.json"}));
  EXPECT_EQ(listed(BrowserPurpose::sessionFile), (Names{"views", "tf.json"}));
  EXPECT_EQ(listed(BrowserPurpose::exportImage), (Names{"views", "float.exr", "shot.png", "shot.TIF"}));
  EXPECT_EQ(listed(BrowserPurpose::seriesFolder), (Names{"views"}));
  EXPECT_EQ(listed(BrowserPurpose::labelsFile), (Names{"views", "scan.mha"}));
  EXPECT_EQ(listed(BrowserPurpose::glyphCenterlines), (Names{"views", "c.vtp", "tf.json"}));
}

TEST(GuiFileBrowser, ATypedPathReplacesTheFolderUnlessRelativeAndHomeIsExpanded) {
  const fs::path folder = "/data/a", home = "/home/reader";
  EXPECT_EQ(angio::resolveTypedPath(folder, "/b/scan.mha", home), fs::path("/b/scan.mha"));
  // Pasted with blanks or quotes around it: still the absolute path, not folder/" /b/...".
  EXPECT_EQ(angio::resolveTypedPath(folder, "  /b/scan.mha \n", home), fs::path("/b/scan.mha"));
  EXPECT_EQ(angio::resolveTypedPath(folder, "'/b/my scan.mha'", home), fs::path("/b/my scan.mha"));
  EXPECT_EQ(angio::resolveTypedPath(folder, "\"/b/c\"", home), fs::path("/b/c"));
  EXPECT_EQ(angio::resolveTypedPath(folder, "~/ct/x.nrrd", home), fs::path("/home/reader/ct/x.nrrd"));
  EXPECT_EQ(angio::resolveTypedPath(folder, "~", home), home);
  EXPECT_EQ(angio::resolveTypedPath(folder, "scan.mha", home), fs::path("/data/a/scan.mha"));
  EXPECT_EQ(angio::resolveTypedPath(folder, "../b/./x.mha", home), fs::path("/data/b/x.mha"));
  EXPECT_EQ(angio::resolveTypedPath(folder, "   ", home), folder);
}

// The Cancel button's hook: a progress callback that throws LoadCancelled stops readVolume, and
// the exception arrives as itself (not as a load error).
TEST_F(GuiData, ProgressCallbackCancelsALoad) {
  angio::ReadOptions read;
  int calls = 0;
  read.progress = [&](double) {
    if (++calls == 2) throw angio::LoadCancelled();
  };
  EXPECT_THROW(angio::readVolume(volume_, read), angio::LoadCancelled);
  EXPECT_EQ(calls, 2);
}

TEST_F(GuiData, CorruptFileKeepsThePreviousDatasetAndShowsTheError) {
  std::ofstream(dir_ / "corrupt.mha") << "ObjectType = Image\nNDims = banana\n";
  const GuiRun run =
      runScript(R"([{"open": ")" + file("corrupt.mha") + R"("}, {"wait_level": "high"}])");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json end = readJson(dir_ / "end.json");
  const Json& data = end["runtime"]["data"];
  EXPECT_EQ(data["name"], "phantom 96x96x200");
  EXPECT_EQ(data["dims"], Json({96, 96, 200}));
  const std::string error = data["load_error"];
  EXPECT_EQ(error.rfind(file("corrupt.mha") + ": ", 0), 0u) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  EXPECT_EQ(data["recent_files"].size(), 0u);
  EXPECT_EQ(end["runtime"]["shown"]["level"], "high");  // the phantom still renders
}

TEST_F(GuiData, ASessionWhoseDatasetFailsToLoadChangesNothing) {
  std::ofstream(dir_ / "corrupt.mha") << "ObjectType = Image\nNDims = banana\n";
  std::ofstream(dir_ / "s.json") << Json({{"dataset", file("corrupt.mha")},
                                          {"view", {{"angle_deg", 45}, {"axis", "k"}}},
                                          {"transfer_function",
                                           {{"name", "the session's"},
                                            {"points",
                                             {{{"hu", -1024}, {"color", {0, 0, 0}}, {"opacity", 0}},
                                              {{"hu", 3071}, {"color", {1, 1, 1}}, {"opacity", 1}}}}}}})
                                        .dump();
  const Json start = startup();
  const Json& layout = start["runtime"]["layout"];
  const GuiRun run = runScript(R"([{"click": )" + centre(layout["session_path"]) +
                               R"(}, {"key": "Ctrl+A"}, {"text": ")" + file("s.json") +
                               R"("}, {"key": "Enter"}, {"click": )" + centre(layout["session_load"]) +
                               R"(}, {"wait_level": "high"}])");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json end = readJson(dir_ / "end.json");
  EXPECT_EQ(end["runtime"]["data"]["name"], "phantom 96x96x200");
  const std::string error = end["runtime"]["data"]["load_error"];
  EXPECT_EQ(error.rfind(file("corrupt.mha") + ": ", 0), 0u) << error;
  EXPECT_NE(error.find("the session was not applied"), std::string::npos) << error;
  // Nothing of the session: the view and the TF are those from before.
  EXPECT_EQ(end["state"]["view"], start["state"]["view"]);
  EXPECT_EQ(end["state"]["transfer_function"], start["state"]["transfer_function"]);
  EXPECT_EQ(end["runtime"]["shown"]["level"], "high");
}

TEST_F(GuiData, SavedSessionRestoresWithTheOptionAndTheLoadButton) {
  const Json layout = startup()["runtime"]["layout"];
  const std::string session = file("my-session.json");
  // Open the volume, turn 10 degrees, save the session.
  const std::string save = R"([
    {"open": ")" + volume_.string() +
                           R"("}, {"wait_level": "fast"},
    {"key": "Shift+Left"},
    {"click": )" + centre(layout["session_path"]) +
                           R"(}, {"key": "Ctrl+A"}, {"text": ")" + session + R"("},
    {"key": "Enter"}, {"click": )" +
                           centre(layout["session_save"]) + R"(}, {"wait_level": "fast"}])";
  GuiRun run = runScript(save);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  ASSERT_TRUE(fs::exists(session));
  const Json saved = readJson(session);
  EXPECT_EQ(saved["dataset"], volume_.string());
  EXPECT_DOUBLE_EQ(saved["view"]["angle_deg"].get<double>(), 10);

  // --session: the session's dataset and view.
  run = runAngioray(kGui + " --session " + session + " --state-out " + file("restored.json"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json restored = readJson(dir_ / "restored.json");
  EXPECT_EQ(restored["runtime"]["data"]["dims"], Json({64, 64, 128}));
  EXPECT_DOUBLE_EQ(restored["state"]["view"]["angle_deg"].get<double>(), 10);
  EXPECT_EQ(restored["state"]["transfer_function"], saved["transfer_function"]);

  // The Load session button: the same, from the phantom.
  const std::string load = R"([
    {"click": )" + centre(layout["session_path"]) +
                           R"(}, {"key": "Ctrl+A"}, {"text": ")" + session + R"("},
    {"key": "Enter"}, {"click": )" +
                           centre(layout["session_load"]) + R"(}, {"wait_level": "high"}])";
  run = runScript(load);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json loaded = readJson(dir_ / "end.json");
  EXPECT_EQ(loaded["runtime"]["data"]["dims"], Json({64, 64, 128}));
  EXPECT_DOUBLE_EQ(loaded["state"]["view"]["angle_deg"].get<double>(), 10);
}

TEST_F(GuiData, CorruptSessionIsAOneLineError) {
  std::ofstream(dir_ / "broken.json") << R"({"view": {"zoom": "big"}})";
  const GuiRun run = runAngioray(kGui + " --session " + file("broken.json"));
  EXPECT_NE(run.exitCode, 0);
  EXPECT_EQ(run.output.rfind("angioray: error: " + file("broken.json") + ": ", 0), 0u) << run.output;
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
}

TEST_F(GuiData, LastSessionIsOfferedOnStartAndRestores) {
  fs::create_directories(dir_ / "config" / "angioray");
  std::ofstream(dir_ / "config" / "angioray" / "last-session.json")
      << Json({{"dataset", volume_.string()},
               {"view", {{"angle_deg", 45}, {"axis", "k"}}},
               {"recent_files", {volume_.string()}}})
             .dump();
  const Json start = startup();
  EXPECT_EQ(start["runtime"]["data"]["session_offered"], volume_.string());
  EXPECT_EQ(start["runtime"]["data"]["recent_files"], Json({volume_.string()}));
  const GuiRun run =
      runScript(R"([{"wait_ms": 200}, {"click": )" +
                centre(start["runtime"]["layout"]["session_restore"]) + R"(}, {"wait_level": "high"}])");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json end = readJson(dir_ / "end.json");
  EXPECT_EQ(end["runtime"]["data"]["session_offered"], "");
  EXPECT_EQ(end["runtime"]["data"]["dims"], Json({64, 64, 128}));
  EXPECT_DOUBLE_EQ(end["state"]["view"]["angle_deg"].get<double>(), 45);
  // Started on a volume, nothing is offered.
  const Json withVolume = startup(" " + volume_.string());
  EXPECT_EQ(withVolume["runtime"]["data"]["session_offered"], "");
}

TEST_F(GuiData, RotationSeriesFromTheExportSectionReproducesFromItsSidecars) {
  const Json layout = startup(" " + volume_.string())["runtime"]["layout"];
  const std::string folder = file("series");
  const std::string steps = R"([
    {"click": )" + centre(layout["series_folder"]) +
                            R"(}, {"key": "Ctrl+A"}, {"text": ")" + folder + R"("},
    {"key": "Enter"},
    {"click": )" + centre(layout["series_count"]) +
                            R"(}, {"key": "Ctrl+A"}, {"text": "3"}, {"key": "Enter"},
    {"click": )" + centre(layout["series_button"]) +
                            R"(}, {"wait_level": "high"}])";
  const GuiRun run = runScript(steps, " " + volume_.string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Json end = readJson(dir_ / "end.json");
  EXPECT_NE(end["runtime"]["message"].get<std::string>().find("exported 3 of 3 views"),
            std::string::npos)
      << end["runtime"]["message"];
  for (const char* name : {"view-000.png", "view-001.png", "view-002.png"}) {
    EXPECT_TRUE(fs::exists(fs::path(folder) / name)) << name;
    EXPECT_TRUE(fs::exists(fs::path(folder) / (std::string(name) + ".json"))) << name;
  }
  const Json last = readJson(fs::path(folder) / "view-002.png.json");
  EXPECT_DOUBLE_EQ(last["view"]["angle_deg"].get<double>(), 240);  // 3 views over a full turn
  // `angioray render --params` renders the same pixels from the sidecar alone.
  const fs::path again = dir_ / "again.png";
  const GuiRun render =
      runAngioray("render --params " + (fs::path(folder) / "view-002.png.json").string() + " --out " +
                  again.string());
  ASSERT_EQ(render.exitCode, 0) << render.output;
  EXPECT_EQ(rgb8Of(again), rgb8Of(fs::path(folder) / "view-002.png"));
}

}  // namespace
