// Session files: a saved session loads back field for field; bad files are one-line InputErrors
// naming the file; the last session lives under XDG_CONFIG_HOME; recent files stay unique and few.
#include "io/session_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

#include "io/input_error.h"

namespace angio {
namespace {

namespace fs = std::filesystem;

class SessionFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("angioray_session_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME")) savedXdg_ = xdg;
  }
  void TearDown() override {
    if (savedXdg_) setenv("XDG_CONFIG_HOME", savedXdg_->c_str(), 1);
    else unsetenv("XDG_CONFIG_HOME");
    fs::remove_all(dir_);
  }

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path file = dir_ / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

  // Loading `text` must throw one line naming the file and containing `problem`.
  void expectRejected(const std::string& text, const std::string& problem) {
    const fs::path file = write("bad-session.json", text);
    try {
      loadSession(file);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
      EXPECT_NE(message.find(problem), std::string::npos) << "wanted \"" << problem << "\" in " << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }

  fs::path dir_;
  std::optional<std::string> savedXdg_;
};

// Every field away from its default, so a field that is not written or not read shows.
Session unusualSession() {
  Session s;
  s.dataset = "/data/cta/aorta.mha";
  s.view = {Axis::j, 123.25, 2.5, {-40.5, 17.0}, 0.8, true, -45};
  s.tf.name = "my vessels";
  s.tf.points = {{-200, {0.1f, 0.2f, 0.3f}, 0.0}, {350, {0.9f, 0.4f, 0.25f}, 0.6}};
  s.tf.modulators = {0.75, 35};
  s.tf.mipWindow = 900;
  s.tf.mipLevel = 320;
  s.tfPreset = "";
  s.mode = Compositing::mip;
  s.shading = {false, 0.45, 0.55};
  s.levels[0] = {2.0, 1.5, Filter::nearest, 0.9};
  s.levels[2] = {0.25, 0.125, Filter::mean, 1.0};
  s.cpr = {true, CprMode::projected, 1, CprColouring::focusTf, true, 3.5};
  s.panelsOpen = {{"Data", true}, {"Transfer function", false}};
  s.recentFiles = {"/data/b.nrrd", "/data/dicom/series1"};
  return s;
}

TEST_F(SessionFileTest, SavedSessionLoadsBackFieldForField) {
  const Session saved = unusualSession();
  const fs::path file = dir_ / "sub" / "session.json";  // the folder is created
  saveSession(saved, file);
  const Session loaded = loadSession(file);
  EXPECT_EQ(loaded.dataset, saved.dataset);
  EXPECT_EQ(loaded.view.axis, Axis::j);
  EXPECT_DOUBLE_EQ(loaded.view.angleDeg, 123.25);
  EXPECT_DOUBLE_EQ(loaded.view.zoom, 2.5);
  EXPECT_DOUBLE_EQ(loaded.view.panPx.x, -40.5);
  EXPECT_DOUBLE_EQ(loaded.view.panPx.y, 17.0);
  EXPECT_DOUBLE_EQ(loaded.view.degreesPerPixel, 0.8);
  EXPECT_TRUE(loaded.view.autoSpin);
  EXPECT_DOUBLE_EQ(loaded.view.spinDegreesPerSecond, -45);
  EXPECT_EQ(loaded.tf.name, "my vessels");
  ASSERT_EQ(loaded.tf.points.size(), 2u);
  EXPECT_DOUBLE_EQ(loaded.tf.points[1].hu, 350);
  EXPECT_FLOAT_EQ(loaded.tf.points[1].color.g, 0.4f);
  EXPECT_DOUBLE_EQ(loaded.tf.points[1].opacity, 0.6);
  EXPECT_DOUBLE_EQ(loaded.tf.modulators.opacityScale, 0.75);
  EXPECT_DOUBLE_EQ(loaded.tf.modulators.huShift, 35);
  EXPECT_DOUBLE_EQ(loaded.tf.mipWindow, 900);
  EXPECT_DOUBLE_EQ(loaded.tf.mipLevel, 320);
  EXPECT_EQ(loaded.mode, Compositing::mip);
  EXPECT_FALSE(loaded.shading.enabled);
  EXPECT_DOUBLE_EQ(loaded.shading.ka, 0.45);
  EXPECT_DOUBLE_EQ(loaded.shading.kd, 0.55);
  for (int q = 0; q < kQualityLevels; ++q) {
    EXPECT_DOUBLE_EQ(loaded.levels[q].isd, saved.levels[q].isd) << q;
    EXPECT_DOUBLE_EQ(loaded.levels[q].osd, saved.levels[q].osd) << q;
    EXPECT_EQ(loaded.levels[q].filter, saved.levels[q].filter) << q;
    EXPECT_DOUBLE_EQ(loaded.levels[q].ert, saved.levels[q].ert) << q;
  }
  EXPECT_TRUE(loaded.cpr.shown);
  EXPECT_EQ(loaded.cpr.mode, CprMode::projected);
  EXPECT_EQ(loaded.cpr.path, 1);
  EXPECT_EQ(loaded.cpr.colouring, CprColouring::focusTf);
  EXPECT_TRUE(loaded.cpr.hybrid);
  EXPECT_DOUBLE_EQ(loaded.cpr.transitionMm, 3.5);
  EXPECT_EQ(loaded.panelsOpen, saved.panelsOpen);
  EXPECT_EQ(loaded.recentFiles, saved.recentFiles);
  // Atomic write: nothing but the session in its folder.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "sub"), fs::directory_iterator()), 1);
}

TEST_F(SessionFileTest, MissingKeysKeepTheDefaults) {
  const Session loaded = loadSession(write("partial.json", R"({"dataset": "x.mha", "view": {"angle_deg": 90}})"));
  const Session defaults;
  EXPECT_EQ(loaded.dataset, "x.mha");
  EXPECT_DOUBLE_EQ(loaded.view.angleDeg, 90);
  EXPECT_EQ(loaded.view.axis, defaults.view.axis);
  EXPECT_DOUBLE_EQ(loaded.view.zoom, defaults.view.zoom);
  EXPECT_DOUBLE_EQ(loaded.levels[2].isd, defaults.levels[2].isd);
  EXPECT_FALSE(loaded.cpr.hybrid);
  EXPECT_EQ(loaded.cpr.path, -1);
}

TEST_F(SessionFileTest, BadSessionsAreOneLineErrorsNamingTheFile) {
  expectRejected("{\"dataset\": ", "not valid JSON");
  expectRejected("[1, 2]", "a session is a JSON object");
  expectRejected(R"({"format": "something-else"})", "not an angioray session");
  expectRejected(R"({"view": {"zoom": "big"}})", "zoom is not a number");
  expectRejected(R"({"view": {"zoom": -1}})", "zoom");
  expectRejected(R"({"view": {"axis": "x"}})", "axis");
  expectRejected(R"({"mode": "xray"})", "mode");
  expectRejected(R"({"levels": {"high": {"filter": "cubic"}}})", "filter");
  expectRejected(R"({"panels": {"Data": 1}})", "panels Data");
  expectRejected(R"({"cpr": {"colouring": "purple"}})", "cpr colouring");
  expectRejected(R"({"cpr": {"mode": "curved"}})", "cpr mode");
  expectRejected(R"({"cpr": {"path": 1.5}})", "cpr path");
  expectRejected(R"({"cpr": {"path": -2}})", "path");
  expectRejected(R"({"cpr": {"transition_mm": -1}})", "transition_mm");
  expectRejected(R"({"cpr": {"hybrid": "yes"}})", "hybrid is not true or false");
  expectRejected(R"({"transfer_function": {"name": "t", "points": [{"hu": 0}]}})", "point 1");
}

TEST_F(SessionFileTest, MissingFileIsAnInputError) {
  EXPECT_THROW(loadSession(dir_ / "none.json"), InputError);
}

TEST_F(SessionFileTest, LastSessionLivesUnderXdgConfigHome) {
  setenv("XDG_CONFIG_HOME", dir_.c_str(), 1);
  EXPECT_EQ(lastSessionPath(), dir_ / "angioray" / "last-session.json");
  saveSession(unusualSession(), lastSessionPath());
  EXPECT_TRUE(fs::exists(dir_ / "angioray" / "last-session.json"));
}

TEST_F(SessionFileTest, RecentFilesAreUniqueNewestFirstAndAtMostTen) {
  std::vector<std::string> recent;
  for (int n = 0; n < 12; ++n) addRecentFile(recent, "/data/" + std::to_string(n) + ".mha");
  ASSERT_EQ(recent.size(), kMaxRecentFiles);
  EXPECT_EQ(recent.front(), "/data/11.mha");
  EXPECT_EQ(recent.back(), "/data/2.mha");
  addRecentFile(recent, "/data/5.mha");
  EXPECT_EQ(recent.size(), kMaxRecentFiles);
  EXPECT_EQ(recent.front(), "/data/5.mha");
  EXPECT_EQ(std::count(recent.begin(), recent.end(), "/data/5.mha"), 1);
}

}  // namespace
}  // namespace angio
