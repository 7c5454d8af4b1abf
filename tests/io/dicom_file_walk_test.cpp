// The walk of a DICOM folder before GDCM reads any of it: files that end inside their meta group or
// an element header are refused with one line (GDCM asserts on them); what is not a DICOM image
// (a stray file, a DICOMDIR-like file without pixel data) is skipped and the series still loads;
// slices are grouped by the SeriesInstanceUID of the data set itself.
#include "io/dicom_file_walk.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "io/input_error.h"
#include "io/volume_reader.h"
#include "tests/support/dicom_series_writer.h"
#include "tests/support/dicom_tag_patch.h"
#include "tests/support/dicom_folder_test.h"

namespace angio {
namespace {

namespace fs = std::filesystem;
using test_support::fileBytes;
using test_support::littleEndian;
using test_support::overwrite;

constexpr const char* kSeriesUid = "1.2.826.0.1.3680043.2.1125.777.4";

class DicomFileWalkTest : public test_support::DicomFolderTest {
 protected:
  // Four slices 2.5 mm apart; returns the one the test changes.
  fs::path series() {
    test_support::writeDicomSeries(dir_, {0, 1, 2, 3}, kSeriesUid, 7);
    return dir_ / "IM2-4.dcm";
  }
  // Where the file meta group ends: its group length (0002,0000) counts the bytes after itself.
  static std::size_t metaGroupEnd(const std::string& bytes) {
    const std::uint32_t length = std::uint8_t(bytes[140]) | std::uint8_t(bytes[141]) << 8 |
                                 std::uint8_t(bytes[142]) << 16 |
                                 std::uint32_t(std::uint8_t(bytes[143])) << 24;
    return 144 + length;
  }
};

TEST_F(DicomFileWalkTest, AnUntouchedSliceGivesItsSeriesAndPixelData) {
  const auto facts = walkDicomFile(dir_, series());
  ASSERT_TRUE(facts.has_value());
  EXPECT_EQ(facts->seriesUid, kSeriesUid);
  EXPECT_TRUE(facts->hasPixelData);
}

TEST_F(DicomFileWalkTest, AFileEndingInsideItsMetaGroupIsRefused) {
  const fs::path slice = series();
  const std::string bytes = fileBytes(slice);
  overwrite(slice, bytes.substr(0, metaGroupEnd(bytes)));
  EXPECT_NE(refusal().find("slice IM2-4.dcm: the file ends inside its file meta group"),
            std::string::npos);
}

TEST_F(DicomFileWalkTest, AFileEndingInsideAnElementHeaderIsRefused) {
  const fs::path slice = series();
  const std::string bytes = fileBytes(slice);
  const std::size_t pixelData = bytes.find(littleEndian(0x7fe0, 2) + littleEndian(0x0010, 2));
  ASSERT_NE(pixelData, std::string::npos);
  overwrite(slice, bytes.substr(0, pixelData + 6));
  EXPECT_NE(refusal().find("slice IM2-4.dcm: the file ends 6 bytes into an element header"),
            std::string::npos);
}

TEST_F(DicomFileWalkTest, StrayFilesAndDicomWithoutPixelDataAreSkipped) {
  series();
  overwrite(dir_ / "notes.txt", "not DICOM\n");
  // "DICM" at the wrong place: GDCM would still try to read this (and assert); the walk skips it.
  overwrite(dir_ / "garbage", std::string(192, '\0') + "DICM" + std::string(64, '\xff'));
  // A DICOM file with a meta group and a patient's name but no image, as a DICOMDIR or a report is.
  const std::string slice = fileBytes(dir_ / "IM2-4.dcm");
  const std::string name =
      littleEndian(0x0010, 2) + littleEndian(0x0010, 2) + littleEndian(4, 4) + "DOE ";
  overwrite(dir_ / "REPORT", slice.substr(0, metaGroupEnd(slice)) + name);
  EXPECT_EQ(refusal(), "");
  EXPECT_EQ(loaded_.volume.dims, glm::ivec3(16, 16, 4));
}

TEST_F(DicomFileWalkTest, ADeflatedDataSetIsRefusedByName) {
  const fs::path slice = series();
  // The slice's preamble, then a meta group naming the deflated syntax and some zlib-like bytes.
  const std::string uid = "1.2.840.10008.1.2.1.99";
  const std::string syntax = littleEndian(0x0002, 2) + littleEndian(0x0010, 2) + "UI" +
                             littleEndian(24, 2) + uid + std::string(24 - uid.size(), '\0');
  const std::string groupLength = littleEndian(0x0002, 2) + littleEndian(0x0000, 2) + "UL" +
                                  littleEndian(4, 2) + littleEndian(std::uint32_t(syntax.size()), 4);
  overwrite(slice, fileBytes(slice).substr(0, 132) + groupLength + syntax + std::string(16, 'x'));
  EXPECT_NE(refusal().find("slice IM2-4.dcm: its data set is deflated (transfer syntax " + uid + ")"),
            std::string::npos);
}

}  // namespace
}  // namespace angio
