// Transfer-function files: the shipped presets, round trips, and one InputError per kind of bad
// input, each naming the file.
#include "io/tf_file.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <random>
#include <string>

#include "io/input_error.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

namespace fs = std::filesystem;

class TfFileTest : public test_support::TempFolderTest {
 protected:
  // Loading `text` must throw an InputError naming the file and containing `problem`.
  void expectRejected(const std::string& text, const std::string& problem) {
    SCOPED_TRACE(text);
    const fs::path file = write("bad_tf.json", text);
    test_support::expectInputError([&] { loadTransferFunction(file); }, file, problem);
  }
};

std::string pointsJson(const std::string& points) {
  return R"({"name": "t", "points": [)" + points + "]}";
}

// One control point, each value given as JSON text; the defaults are valid.
struct PointText {
  std::string hu = "5", color = "[0, 0, 0]", opacity = "0";
};

std::string json(const PointText& p) {
  return R"({"hu": )" + p.hu + R"(, "color": )" + p.color + R"(, "opacity": )" + p.opacity + "}";
}

const std::string kGood0 = R"({"hu": -1024, "color": [0, 0, 0], "opacity": 0})";
const std::string kGood1 = R"({"hu": 300, "color": [0.9, 0.3, 0.2], "opacity": 0.4})";

void expectSameTf(const TransferFunction& a, const TransferFunction& b) {
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_EQ(a.points[i].hu, b.points[i].hu) << i;
    EXPECT_EQ(a.points[i].color, b.points[i].color) << i;
    EXPECT_EQ(a.points[i].opacity, b.points[i].opacity) << i;
  }
  EXPECT_EQ(a.modulators.opacityScale, b.modulators.opacityScale);
  EXPECT_EQ(a.modulators.huShift, b.modulators.huShift);
  EXPECT_EQ(a.mipWindow, b.mipWindow);
  EXPECT_EQ(a.mipLevel, b.mipLevel);
}

TransferFunction presetNamed(const std::string& id) {
  for (const Preset& preset : listPresets())
    if (preset.id == id) return loadTransferFunction(preset.file);
  ADD_FAILURE() << "no preset " << id;
  return {};
}

TEST(TfPresets, AllFiveShippedPresetsAreListedSortedById) {
  const std::vector<Preset> presets = listPresets();
  std::vector<std::string> ids;
  for (const Preset& preset : presets) ids.push_back(preset.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"bone", "cta-vessels", "cta-vessels-bone", "mip-cta",
                                           "soft-tissue-context"}));
}

TEST(TfPresets, EveryPresetLoadsWithAtLeastThreeValidPoints) {
  for (const Preset& preset : listPresets()) {
    SCOPED_TRACE(preset.id);
    const TransferFunction tf = loadTransferFunction(preset.file);
    EXPECT_FALSE(tf.name.empty());
    ASSERT_GE(tf.points.size(), 3u);
    for (std::size_t i = 0; i < tf.points.size(); ++i) {
      const ControlPoint& p = tf.points[i];
      EXPECT_GE(p.opacity, 0.0);
      EXPECT_LE(p.opacity, 1.0);
      if (i > 0) {
        EXPECT_LE(tf.points[i - 1].hu, p.hu);
      }
    }
    EXPECT_GT(tf.mipWindow, 0);
    EXPECT_TRUE(buildTable(tf).anyVisible(0, kDensityLevels - 1));
  }
}

TEST(TfPresets, CtaVesselsShowsLumenAndHidesSoftTissue) {
  const TransferFunction tf = presetNamed("cta-vessels");
  EXPECT_EQ(tf.name, "CTA vessels");
  for (double hu = 250; hu <= 600; hu += 5) EXPECT_GT(evaluate(tf, hu).a, 0.2f) << hu;
  for (double hu = -1024; hu < 100; hu += 5) EXPECT_EQ(evaluate(tf, hu).a, 0.f) << hu;
  EXPECT_EQ(tf.mipWindow, 800);
  EXPECT_EQ(tf.mipLevel, 300);
}

TEST(TfPresets, BoneShowsBoneAndNotLumen) {
  const TransferFunction tf = presetNamed("bone");
  EXPECT_EQ(tf.name, "Bone");
  for (double hu = 800; hu <= 3071; hu += 10) EXPECT_GE(evaluate(tf, hu).a, 0.5f) << hu;
  EXPECT_LT(evaluate(tf, 300).a, 0.05f);
  EXPECT_EQ(evaluate(tf, 200).a, 0.f);
}

TEST_F(TfFileTest, ParsesPointsSortsThemAndReadsOptionalKeys) {
  const fs::path file = write("mine.json", R"({"name": "Mine", "description": "ignored",
      "mode": "mip", "points": [)" + kGood1 + "," +
                                               kGood0 + R"(],
      "mip": {"window": 900, "level": 350},
      "modulators": {"opacity_scale": 0.5, "hu_shift": -20}})");
  const TransferFunction tf = loadTransferFunction(file);
  EXPECT_EQ(tf.name, "Mine");
  ASSERT_EQ(tf.points.size(), 2u);
  EXPECT_EQ(tf.points[0].hu, -1024);  // sorted by hu
  EXPECT_EQ(tf.points[1].hu, 300);
  EXPECT_EQ(tf.points[1].color, glm::vec3(0.9f, 0.3f, 0.2f));
  EXPECT_EQ(tf.points[1].opacity, 0.4);
  EXPECT_EQ(tf.mipWindow, 900);
  EXPECT_EQ(tf.mipLevel, 350);
  EXPECT_EQ(tf.modulators.opacityScale, 0.5);
  EXPECT_EQ(tf.modulators.huShift, -20);
}

TEST_F(TfFileTest, MissingOptionalKeysKeepDefaults) {
  const TransferFunction tf = loadTransferFunction(write("plain.json", pointsJson(kGood0)));
  const TransferFunction defaults;
  EXPECT_EQ(tf.mipWindow, defaults.mipWindow);
  EXPECT_EQ(tf.mipLevel, defaults.mipLevel);
  EXPECT_EQ(tf.modulators.opacityScale, 1.0);
  EXPECT_EQ(tf.modulators.huShift, 0.0);
}

TEST_F(TfFileTest, RoundTripsThroughSave) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> hu(-1024, 3071), unit(0, 1);
  TransferFunction tf;
  tf.name = "Round \"trip\" \xC3\xA9";  // quotes and UTF-8 survive
  for (int i = 0; i < 9; ++i) {
    tf.points.push_back({hu(rng), {float(unit(rng)), float(unit(rng)), float(unit(rng))}, unit(rng)});
  }
  tf.points.push_back({-1024, {0.6f, 0.1f, 0.05f}, 0});
  tf.points.push_back({3071, {1.f, 1.f, 1.f}, 1});
  sortPoints(tf);
  tf.modulators = {1.7, -33.25};
  tf.mipWindow = 1234.5;
  tf.mipLevel = -17;
  const fs::path file = dir_ / "saved.json";
  saveTransferFunction(tf, file);
  expectSameTf(loadTransferFunction(file), tf);
  // Saving again over the file replaces it and leaves only that file in the directory.
  tf.name = "second";
  saveTransferFunction(tf, file);
  EXPECT_EQ(loadTransferFunction(file).name, "second");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(TfFileTest, SavedFileIsReadableJson) {
  TransferFunction tf = presetNamed("cta-vessels");
  const std::string text = toJson(tf);
  EXPECT_NE(text.find("\"color\":[0.55,0.06,0.03]"), std::string::npos) << text;  // shortest floats
  EXPECT_NE(text.find('\n'), std::string::npos);
  expectSameTf(parseTransferFunction(text, "memory"), tf);
}

TEST_F(TfFileTest, PresetsRoundTrip) {
  for (const Preset& preset : listPresets()) {
    SCOPED_TRACE(preset.id);
    const TransferFunction tf = loadTransferFunction(preset.file);
    const fs::path copy = dir_ / (preset.id + ".json");
    saveTransferFunction(tf, copy);
    expectSameTf(loadTransferFunction(copy), tf);
  }
}

TEST_F(TfFileTest, SaveIntoMissingDirectoryIsAnInputError) {
  const fs::path file = dir_ / "no_such_dir" / "tf.json";
  try {
    saveTransferFunction(presetNamed("bone"), file);
    ADD_FAILURE() << "saved into a missing directory";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
  }
}

TEST_F(TfFileTest, MissingFileIsAnInputError) {
  const fs::path file = dir_ / "absent.json";
  try {
    loadTransferFunction(file);
    ADD_FAILURE();
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(file.string() + ": no such file"), std::string::npos)
        << error.what();
  }
}

TEST_F(TfFileTest, DirectoryIsAnInputError) { EXPECT_THROW(loadTransferFunction(dir_), InputError); }

TEST_F(TfFileTest, InvalidJsonReportsTheBytePosition) {
  // nlohmann counts bytes from 1 up to the offending character.
  const std::string text = R"({"name": "t", "points": [)" + kGood0 + ", oops]}";
  expectRejected(text, "not valid JSON at byte " + std::to_string(text.find("oops") + 1));
  expectRejected("", "not valid JSON at byte 1");
  expectRejected(R"({"name": "t")", "not valid JSON");
}

TEST_F(TfFileTest, RejectsBadStructure) {
  expectRejected("[1, 2]", "expected a JSON object");
  expectRejected(R"({"name": "t"})", "has no \"points\"");
  expectRejected(R"({"name": "t", "points": []})", "\"points\" is empty");
  expectRejected(R"({"name": "t", "points": {"hu": 1}})", "\"points\" is not an array");
  expectRejected(R"({"name": 5, "points": [)" + kGood0 + "]}", "\"name\" is not a string");
  expectRejected(pointsJson(kGood0 + ", 7"), "point 2 is not an object");
}

TEST_F(TfFileTest, RejectsPointsWithMissingKeys) {
  expectRejected(pointsJson(R"({"color": [0, 0, 0], "opacity": 0})"), "point 1 has no \"hu\"");
  expectRejected(pointsJson(kGood0 + R"(, {"hu": 5, "opacity": 0})"), "point 2 has no \"color\"");
  expectRejected(pointsJson(R"({"hu": 5, "color": [0, 0, 0]})"), "point 1 has no \"opacity\"");
}

TEST_F(TfFileTest, RejectsBadColors) {
  for (const char* color : {"[0, 0]", "[0, 0, 0, 0]", R"("red")"})
    expectRejected(pointsJson(json({.color = color})), "point 1: color is not an array of 3 numbers");
  expectRejected(pointsJson(json({.color = R"([0, "NaN", 0])"})), "point 1: color[1] is not a number");
  expectRejected(pointsJson(json({.color = "[0, 0, 1.2]"})), "point 1: color[2] 1.2 outside [0, 1]");
  expectRejected(pointsJson(json({.color = "[-0.1, 0, 0]"})), "point 1: color[0] -0.1 outside [0, 1]");
}

TEST_F(TfFileTest, RejectsNonNumbersAndNonFiniteValues) {
  for (const char* hu : {"null", R"("NaN")"})
    expectRejected(pointsJson(json({.hu = hu})), "point 1: hu is not a number");
  expectRejected(pointsJson(json({.opacity = "true"})), "point 1: opacity is not a number");
  // JSON has no infinity; the parser refuses overflowing numbers rather than returning inf.
  expectRejected(pointsJson(json({.hu = "1e999"})), "not valid JSON: number overflow parsing '1e999'");
  expectRejected(pointsJson(kGood0 + ", " + json({.opacity = "-1e999"})),
                 "not valid JSON: number overflow");
}

TEST_F(TfFileTest, RejectsValuesOutOfRange) {
  expectRejected(pointsJson(kGood0 + "," + kGood1 + ", " + json({.opacity = "1.5"})),
                 "point 3: opacity 1.5 outside [0, 1]");
  expectRejected(pointsJson(json({.opacity = "-0.25"})), "point 1: opacity -0.25 outside [0, 1]");
  expectRejected(pointsJson(json({.hu = "3072"})), "point 1: hu 3072 outside [-1024, 3071]");
  expectRejected(pointsJson(json({.hu = "-1025"})), "point 1: hu -1025 outside [-1024, 3071]");
}

TEST_F(TfFileTest, RejectsBadOptionalBlocks) {
  // One valid point and `keys`.
  const auto withKeys = [](const std::string& keys) {
    return R"({"points": [)" + kGood0 + "], " + keys + "}";
  };
  expectRejected(withKeys(R"("mip": {"window": 0, "level": 1})"), "mip window must be > 0");
  expectRejected(withKeys(R"("mip": {"window": "wide"})"), "mip window is not a number");
  expectRejected(withKeys(R"("mip": 3)"), "\"mip\" is not an object");
  expectRejected(withKeys(R"("modulators": {"opacity_scale": -1})"), "opacity_scale must be >= 0");
  expectRejected(withKeys(R"("modulators": {"hu_shift": null})"), "hu_shift is not a number");
}

TEST_F(TfFileTest, LabelsRoundTripAndTheRenderingModelsExampleParses) {
  const fs::path file = write("labels.json", R"({"name": "t", "points": [)" + kGood0 + R"(],
    "labels": [{"label": 1, "name": "bone", "mode": "hidden"},
               {"label": 3, "name": "left kidney", "mode": "tf", "color": [0.5, 0.25, 1],
                "points": [)" + kGood1 + "," + kGood0 +
                                                 R"(]}]})");
  const TransferFunction tf = loadTransferFunction(file);
  ASSERT_EQ(tf.labels.size(), 2u);
  EXPECT_EQ(tf.labels[0].label, 1);
  EXPECT_EQ(tf.labels[0].name, "bone");
  EXPECT_EQ(tf.labels[0].mode, LabelMode::hidden);
  EXPECT_EQ(tf.labels[1].mode, LabelMode::tf);
  EXPECT_EQ(tf.labels[1].color, glm::vec3(0.5f, 0.25f, 1.f));
  ASSERT_EQ(tf.labels[1].points.size(), 2u);
  EXPECT_EQ(tf.labels[1].points[0].hu, -1024);  // sorted by HU
  const fs::path saved = dir_ / "saved.json";
  saveTransferFunction(tf, saved);
  EXPECT_EQ(loadTransferFunction(saved), tf);
  // A TF without labels is written as before: no "labels" key.
  TransferFunction plain = tf;
  plain.labels.clear();
  EXPECT_EQ(toJson(plain).find("labels"), std::string::npos);
}

TEST_F(TfFileTest, RejectsBadLabels) {
  const auto withLabels = [](const std::string& labels) {
    return R"({"points": [)" + kGood0 + R"(], "labels": )" + labels + "}";
  };
  expectRejected(withLabels("{}"), "\"labels\" is not an array");
  expectRejected(withLabels(R"([{"label": 16, "mode": "hidden"}])"), "label 16 outside [1, 15]");
  expectRejected(withLabels(R"([{"label": 0, "mode": "hidden"}])"), "label 0 outside [1, 15]");
  expectRejected(withLabels(R"([{"label": 2.5, "mode": "hidden"}])"), "is not an integer");
  expectRejected(withLabels(R"([{"mode": "hidden"}])"), "has no \"label\"");
  expectRejected(withLabels(R"([{"label": 2, "mode": "invisible"}])"),
                 "label 2: mode \"invisible\" is not main, hidden or tf");
  expectRejected(withLabels(R"([{"label": 2, "mode": "tf"}])"), "label 2: mode tf needs \"points\"");
  expectRejected(withLabels(R"([{"label": 2, "mode": "hidden"}, {"label": 2, "mode": "main"}])"),
                 "label 2 is listed twice");
  expectRejected(withLabels(R"([{"label": 2, "mode": "tf", "points": [{"hu": 1}]}])"),
                 "label 2: point 1 has no \"color\"");
}

TEST_F(TfFileTest, NameDefaultsToTheFileStem) {
  EXPECT_EQ(loadTransferFunction(write("unnamed.json", R"({"points": [)" + kGood0 + "]}")).name,
            "unnamed");
}

TEST_F(TfFileTest, LoadPresetOrFileById) {
  EXPECT_EQ(loadPresetOrFile("cta-vessels").name, "CTA vessels");
  EXPECT_EQ(loadPresetOrFile("cta-vessels-bone").name, "CTA vessels + bone");
}

TEST_F(TfFileTest, LoadPresetOrFileByDisplayNameIgnoringCase) {
  EXPECT_EQ(loadPresetOrFile("CTA vessels").name, "CTA vessels");
  EXPECT_EQ(loadPresetOrFile("soft-TISSUE context").name, "Soft-tissue context");
  expectSameTf(loadPresetOrFile("bone"), loadPresetOrFile("BONE"));
}

TEST_F(TfFileTest, LoadPresetOrFileByPath) {
  const fs::path file = write("custom.json", R"({"name": "Custom", "points": [)" + kGood1 + "]}");
  EXPECT_EQ(loadPresetOrFile(file.string()).name, "Custom");
  // An existing but broken file reports its own problem, not "no such preset".
  const fs::path broken = write("broken.json", "{");
  try {
    loadPresetOrFile(broken.string());
    ADD_FAILURE();
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("not valid JSON"), std::string::npos) << error.what();
  }
}

TEST_F(TfFileTest, LoadPresetOrFileUnknownListsThePresets) {
  try {
    loadPresetOrFile("no-such-thing");
    ADD_FAILURE();
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("no-such-thing: no such preset or file; presets: bone, cta-vessels, "),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("soft-tissue-context"), std::string::npos) << message;
  }
}

TEST_F(TfFileTest, PresetDirectoryCanBeOverriddenByEnvironment) {
  write("only-one.json", R"({"name": "Only one", "points": [)" + kGood1 + "]}");
  write("notes.txt", "not a preset");
  ::setenv("ANGIORAY_PRESET_DIR", dir_.c_str(), 1);
  const std::vector<Preset> presets = listPresets();
  const TransferFunction byName = loadPresetOrFile("only ONE");
  ::unsetenv("ANGIORAY_PRESET_DIR");
  ASSERT_EQ(presets.size(), 1u);
  EXPECT_EQ(presets[0].id, "only-one");
  EXPECT_EQ(byName.name, "Only one");
  EXPECT_EQ(listPresets().size(), 5u);  // back to the shipped presets
}

}  // namespace
}  // namespace angio
