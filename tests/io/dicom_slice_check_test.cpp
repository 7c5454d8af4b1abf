// DICOM slices whose tags contradict their pixel data or do not place them: each is refused with
// one line naming the slice and the tag, before GDCM or ITK would assert or load it wrongly. The
// slices are written by ITK, then one tag's value is rewritten in the file's bytes.
#include "io/dicom_slice_check.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "io/volume_reader.h"
#include "tests/support/dicom_series_writer.h"
#include "tests/support/dicom_tag_patch.h"
#include "tests/support/dicom_folder_test.h"

namespace angio {
namespace {

namespace fs = std::filesystem;
using test_support::writeDicomSeries;

using test_support::setDicomTag;
using test_support::unsignedShort;

class DicomSliceCheckTest : public test_support::DicomFolderTest {
 protected:
  // Four slices 2.5 mm apart; returns the one the test breaks.
  fs::path series() {
    writeDicomSeries(dir_, {0, 1, 2, 3}, "1.2.3.4", 7);
    return dir_ / "IM2-4.dcm";
  }
  // Four slices 2.5 mm apart in z, each `drift` mm further in y than the one before.
  void tiltedStack(double drift) {
    for (int k = 0; k < 4; ++k) {
      test_support::DicomSlice slice;
      slice.fileName = "tilt" + std::to_string(k) + ".dcm";
      slice.position = {-12.0, 30.5 + drift * k, 5.0 + 2.5 * k};
      slice.instanceNumber = k + 1;
      slice.hu = [](int, int) { return short(0); };
      test_support::writeDicomSlice(dir_, slice);
    }
  }
};

TEST_F(DicomSliceCheckTest, AnUntouchedSeriesLoads) {
  series();
  EXPECT_EQ(refusal(), "");
}

TEST_F(DicomSliceCheckTest, ColourSamplesAreRefused) {
  setDicomTag(series(), 0x0028, 0x0002, unsignedShort(3));
  const std::string message = refusal();
  EXPECT_NE(message.find("IM2-4.dcm"), std::string::npos) << message;
  EXPECT_NE(message.find("3 samples per pixel"), std::string::npos) << message;
}

TEST_F(DicomSliceCheckTest, BitsAllocatedThatContradictThePixelDataAreRefused) {
  const fs::path slice = series();
  setDicomTag(slice, 0x0028, 0x0100, unsignedShort(8));
  setDicomTag(slice, 0x0028, 0x0101, unsignedShort(8));
  setDicomTag(slice, 0x0028, 0x0102, unsignedShort(7));
  EXPECT_NE(refusal().find(
                "512 bytes of pixel data where Rows x Columns x BitsAllocated (16 x 16 x 8) need 256"),
            std::string::npos);
}

TEST_F(DicomSliceCheckTest, BitsStoredBeyondBitsAllocatedAreRefused) {
  setDicomTag(series(), 0x0028, 0x0101, unsignedShort(20));
  EXPECT_NE(refusal().find("do not fit BitsAllocated 16"), std::string::npos);
}

TEST_F(DicomSliceCheckTest, HugeRowsOnOneSliceAreRefused) {
  setDicomTag(series(), 0x0028, 0x0010, unsignedShort(65535));
  EXPECT_NE(refusal().find("(65535 x 16 x 16) need"), std::string::npos);
}

TEST_F(DicomSliceCheckTest, AMalformedUnsignedShortIsRefused) {
  setDicomTag(series(), 0x0028, 0x0011, "\x10");
  EXPECT_NE(refusal().find("element (0028,0011) has a value of 1 bytes where DICOM has one US value"),
            std::string::npos);
}

TEST_F(DicomSliceCheckTest, ZeroNegativeOrNanPixelSpacingIsRefused) {
  for (const std::string spacing : {"0\\0.7 ", "-0.7\\0.7", "nan\\0.7", "0.7"}) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    setDicomTag(series(), 0x0028, 0x0030, spacing);
    const std::string message = refusal();
    EXPECT_NE(message.find("PixelSpacing (0028,0030)"), std::string::npos) << spacing << ": " << message;
  }
}

TEST_F(DicomSliceCheckTest, AnAllZeroOrientationIsRefused) {
  setDicomTag(series(), 0x0020, 0x0037, "0\\0\\0\\0\\0\\0 ");
  EXPECT_NE(refusal().find("ImageOrientationPatient (0020,0037) whose rows and columns are not"),
            std::string::npos);
}

TEST_F(DicomSliceCheckTest, NanRescaleSlopeIsRefused) {
  setDicomTag(series(), 0x0028, 0x1053, "nan ");
  EXPECT_NE(refusal().find("invalid RescaleSlope (0028,1053)"), std::string::npos);
}

TEST_F(DicomSliceCheckTest, ZeroRescaleSlopeIsRefused) {
  setDicomTag(series(), 0x0028, 0x1053, "0 ");
  EXPECT_NE(refusal().find("RescaleSlope (0028,1053) of 0"), std::string::npos);
}

TEST_F(DicomSliceCheckTest, ATruncatedSliceIsRefused) {
  test_support::truncateBy(series(), 100);
  const std::string message = refusal();
  EXPECT_NE(
      message.find("slice IM2-4.dcm: element (7fe0,0010) claims 512 bytes where the file has 412 left"),
      std::string::npos)
      << message;
}

TEST_F(DicomSliceCheckTest, AGantryTiltIsRefusedWithItsAngle) {
  // Slices 2.5 mm apart in z that move 0.5 mm in y each: a tilt of atan(0.5 / 2.5) = 11.31 degrees.
  tiltedStack(0.5);
  const std::string message = refusal();
  EXPECT_NE(message.find("gantry tilt of 11.31 degrees"), std::string::npos) << message;
  EXPECT_NE(message.find("not resampled"), std::string::npos) << message;
}

TEST_F(DicomSliceCheckTest, ASmallDriftWithinHalfAPixelStillLoads) {
  tiltedStack(0.05);  // 0.15 mm over the stack, under half of the 0.7 mm pixel
  EXPECT_EQ(refusal(), "");
}

TEST_F(DicomSliceCheckTest, AOneSliceFileIsCheckedToo) {
  const fs::path slice = series();
  setDicomTag(slice, 0x0028, 0x0002, unsignedShort(3));
  try {
    readVolume(slice);
    FAIL() << "loaded";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("3 samples per pixel"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace angio
