#pragma once
// A fixture for the DICOM folder tests: a temporary folder to write a series into, and the one-line
// message reading it gives.
#include <string>

#include <gtest/gtest.h>

#include "io/input_error.h"
#include "io/volume_reader.h"
#include "tests/support/temp_folder_test.h"

namespace angio::test_support {

class DicomFolderTest : public TempFolderTest {
 protected:
  // The message of the error reading the folder (empty when it loads; the volume is in loaded_).
  std::string refusal() {
    try {
      loaded_ = readVolume(dir_);
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_NE(message.find(dir_.string()), std::string::npos) << message;
      return message;
    }
    return "";
  }
  LoadedVolume loaded_;
};

}  // namespace angio::test_support
