// The golden corpus (tests/golden): sidecars and CPR command lines covering every kind of image
// angioray makes, with the hashes of the images they gave when the corpus was recorded. Every
// commit must give the same float pixels, so a refactoring that changes an image fails here.
// ANGIORAY_GOLDEN_RECORD=1 writes tests/golden/hashes.json instead of comparing (see record.sh).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/phantom_folder_test.h"
#include "tests/support/run_angioray.h"

namespace angio {
namespace {

namespace fs = std::filesystem;
using test_support::runAngioray;

const fs::path kGoldenDir = fs::path(ANGIORAY_TEST_DATA).parent_path() / "golden";

std::string readText(const fs::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void replaceAll(std::string& text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

// FNV-1a (64 bit) of the image's float RGBA pixels as decoded from the EXR file.
std::string pixelHash(const fs::path& exr) {
  auto input = OIIO::ImageInput::open(exr.string());
  if (!input) return "unreadable";
  const OIIO::ImageSpec& spec = input->spec();
  std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
  input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data());
  std::uint64_t hash = 1469598103934665603ull;
  const auto* bytes = reinterpret_cast<const unsigned char*>(pixels.data());
  for (std::size_t i = 0; i < pixels.size() * sizeof(float); ++i)
    hash = (hash ^ bytes[i]) * 1099511628211ull;
  char text[32];
  std::snprintf(text, sizeof text, "%dx%d:%016llx", spec.width, spec.height, (unsigned long long)hash);
  return text;
}

class GoldenCorpus : public test_support::PhantomFolderTest {
 protected:
  const char* folderPrefix() const override { return "golden"; }

  std::string withPaths(std::string text, const std::string& out) const {
    const std::string shared = ANGIORAY_SHARED_DATA;
    replaceAll(text, "${PHANTOM_CL}", file("phantom.csv"));
    replaceAll(text, "${PHANTOM}", file("phantom.nrrd"));
    replaceAll(text, "${AORTA_CL}", shared + "/aorta-centerlines.csv");
    replaceAll(text, "${AORTA}", shared + "/aorta.mha");
    replaceAll(text, "${TEST_DATA}", ANGIORAY_TEST_DATA);
    replaceAll(text, "${OUT}", out);
    return text;
  }

  // Renders one case to NAME.exr and returns its hash ("" and a failure if the run failed).
  std::string renderSidecar(const std::string& name, const fs::path& sidecar) {
    const std::string out = file(name + ".exr");
    const std::string params = file(name + ".json");
    std::ofstream(params) << withPaths(readText(sidecar), file(name + ".png"));
    const auto run = runAngioray("render --params " + params + " --out " + out);
    EXPECT_EQ(run.exitCode, 0) << name << ": " << run.output;
    return run.exitCode == 0 ? pixelHash(out) : "";
  }

  std::string renderCommand(const std::string& name, const std::string& arguments) {
    const std::string out = file(name + ".exr");
    const auto run = runAngioray(withPaths(arguments, out));
    EXPECT_EQ(run.exitCode, 0) << name << ": " << run.output;
    return run.exitCode == 0 ? pixelHash(out) : "";
  }
};

TEST_F(GoldenCorpus, EverySidecarAndCprGivesTheRecordedPixels) {
  std::map<std::string, std::string> hashes;
  for (const auto& entry : fs::directory_iterator(kGoldenDir / "sidecars"))
    hashes[entry.path().stem().string()] = renderSidecar(entry.path().stem().string(), entry.path());
  const nlohmann::json cprCases = nlohmann::json::parse(readText(kGoldenDir / "cpr_cases.json"));
  for (const auto& [name, arguments] : cprCases.items())
    hashes[name] = renderCommand(name, arguments.get<std::string>());
  ASSERT_GE(hashes.size(), 30u);

  if (std::getenv("ANGIORAY_GOLDEN_RECORD")) {
    std::ofstream(kGoldenDir / "hashes.json") << nlohmann::json(hashes).dump(2) << "\n";
    GTEST_SKIP() << "recorded " << hashes.size() << " hashes";
  }
  const nlohmann::json recorded = nlohmann::json::parse(readText(kGoldenDir / "hashes.json"));
  EXPECT_EQ(recorded.size(), hashes.size()) << "cases were added or removed without recording";
  for (const auto& [name, hash] : hashes) {
    ASSERT_TRUE(recorded.contains(name)) << name << " has no recorded hash";
    EXPECT_EQ(hash, recorded[name].get<std::string>()) << name << " renders different pixels";
  }
}

}  // namespace
}  // namespace angio
