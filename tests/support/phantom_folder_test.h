#pragma once
// A test fixture with its own temporary folder holding a small generated phantom and its
// centerlines (phantom.nrrd, phantom.csv, 96x96x200; truth.nrrd, its labels, if asked), made by the
// angioray binary under test. The
// folder's name carries the suite, test and process id: ctest runs tests in parallel processes,
// and another build's run may run the same test at the same time.
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_angioray.h"

namespace angio::test_support {

class PhantomFolderTest : public ::testing::Test {
 protected:
  // The folder's name prefix, e.g. "gui-vessel".
  virtual const char* folderPrefix() const = 0;
  // Whether the phantom's ground-truth labels are written too (truth.nrrd: 1 bone, 2 table).
  virtual bool withLabels() const { return false; }

  void SetUp() override {
    dir = std::filesystem::temp_directory_path() /
          ("angioray-" + std::string(folderPrefix()) + "-" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name() + "-" +
           std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto run = runAngioray(
        "phantom " + file("phantom.nrrd") + " --size 96x96x200 --style simple --centerlines " +
        file("phantom.csv") + (withLabels() ? " --labels " + file("truth.nrrd") : ""));
    ASSERT_EQ(run.exitCode, 0) << run.output;
  }
  void TearDown() override { std::filesystem::remove_all(dir); }

  std::string file(const std::string& name) const { return (dir / name).string(); }
  nlohmann::json readJson(const std::string& name) const {
    std::ifstream in(dir / name);
    return nlohmann::json::parse(in);
  }

  std::filesystem::path dir;
};

}  // namespace angio::test_support
