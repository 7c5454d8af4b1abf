// The walk of a DICOM folder before GDCM reads any of it: files that end inside their meta group or
// an element header are refused with one line (GDCM asserts on them); what is not a DICOM image
// (a stray file, a DICOMDIR-like file without pixel data) is skipped and the series still loads;
// slices are grouped by the SeriesInstanceUID of the data set itself.
#include "io/dicom_file_walk.h"

#include <gtest/gtest.h>

#include <gdcmReader.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "io/input_error.h"
#include "io/volume_reader.h"
#include "tests/support/dicom_recompress.h"
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

// GDCM reads a file with "DICM" but no meta group by guessing its syntax: a fuzzed slice whose
// first tag became (0000,0200) OF was read big endian, its length 0xe6000000 allocated.
TEST_F(DicomFileWalkTest, AFileWithoutItsMetaGroupAfterThePreambleIsRefused) {
  const fs::path slice = series();
  std::string bytes = fileBytes(slice);
  bytes.replace(132, 2, littleEndian(0x0000, 2));
  overwrite(slice, bytes);
  EXPECT_NE(refusal().find("slice IM2-4.dcm: has no file meta group (0002) after its preamble"),
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

// Nesting in an implicit VR data set without a meta group (GDCM reads one from byte 0): a tag and a
// 4-byte length, then the value.
std::string implicitElement(std::uint16_t group, std::uint16_t element, std::uint32_t length,
                            const std::string& value = "") {
  return littleEndian(group, 2) + littleEndian(element, 2) + littleEndian(length, 4) + value;
}
constexpr std::uint32_t kUndefined = 0xffffffffu;
const std::string kOpenSequence = implicitElement(0x0008, 0x1115, kUndefined);  // ReferencedSeries
const std::string kOpenItem = implicitElement(0xfffe, 0xe000, kUndefined);
const std::string kItemEnd = implicitElement(0xfffe, 0xe00d, 0);
const std::string kSequenceEnd = implicitElement(0xfffe, 0xe0dd, 0);
const std::string kModality = implicitElement(0x0008, 0x0060, 2, "CT");

// Writes `bytes` to `file` and walks it.
std::optional<DicomFileFacts> walkBytes(const fs::path& file, const std::string& bytes) {
  overwrite(file, bytes);
  return walkDicomFile(file, file);
}

// walkDicomFile's refusal of `bytes` ("" if it walks them).
std::string walkRefusal(const fs::path& file, const std::string& bytes) {
  try {
    walkBytes(file, bytes);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST_F(DicomFileWalkTest, SequencesAndItemsMustBeClosedBeforeTheFileEnds) {
  const fs::path file = dir_ / "nested.dcm";
  const std::string closed = kModality + kOpenSequence + kOpenItem + kModality + kItemEnd + kSequenceEnd;
  EXPECT_EQ(walkRefusal(file, closed), "");
  // GDCM asserts on an item it reaches the end of the file in.
  EXPECT_NE(walkRefusal(file, kModality + kOpenSequence + kOpenItem + kModality)
                .find("the file ends inside an item of undefined length"),
            std::string::npos);
  EXPECT_NE(walkRefusal(file, kModality + kOpenSequence + kOpenItem + kModality + kItemEnd)
                .find("the file ends inside a sequence of undefined length"),
            std::string::npos);
  // GDCM asserts on a sequence's delimiter inside an item of undefined length too.
  EXPECT_NE(walkRefusal(file, kModality + kOpenSequence + kOpenItem + kSequenceEnd)
                .find("element (fffe,e0dd) ends a sequence inside an item that was not ended"),
            std::string::npos);
}

TEST_F(DicomFileWalkTest, AnItemLongerThanTheFileIsRefusedBeforeGdcmAllocatesIt) {
  const fs::path file = dir_ / "long-item.dcm";
  const std::string item = implicitElement(0xfffe, 0xe000, 0xffffff00u);
  EXPECT_NE(walkRefusal(file, kModality + kOpenSequence + item + kModality + kSequenceEnd)
                .find("element (fffe,e000) claims 4294967040 bytes where the file has 18 left"),
            std::string::npos);
  EXPECT_NE(
      walkRefusal(file, kModality + kOpenItem + kModality).find("is an item tag outside a sequence"),
      std::string::npos);
}

TEST_F(DicomFileWalkTest, EncapsulatedPixelDataIsSteppedOverFragmentByFragment) {
  const fs::path file = dir_ / "fragments.dcm";
  const std::string pixels = implicitElement(0x7fe0, 0x0010, kUndefined);
  const std::string offsets = implicitElement(0xfffe, 0xe000, 0);
  // Fragment bytes that would read as a broken element header if the walk went into them.
  const std::string fragment = implicitElement(0xfffe, 0xe000, 8, "\xff\xd8\xff\xc3\xff\xff\xff\xff");
  const auto walked = walkBytes(file, kModality + pixels + offsets + fragment + fragment + kSequenceEnd);
  ASSERT_TRUE(walked.has_value());
  EXPECT_TRUE(walked->hasPixelData);
  EXPECT_NE(walkRefusal(file, kModality + pixels + offsets + fragment)
                .find("the file ends inside its encapsulated pixel data"),
            std::string::npos);
  EXPECT_NE(walkRefusal(file, kModality + pixels + kOpenItem + kSequenceEnd)
                .find("is a pixel data fragment of undefined length"),
            std::string::npos);
  // GDCM reads the delimiter as a fragment and allocates its length (1.3 GB here: a fuzz finding).
  const std::string longEnd = implicitElement(0xfffe, 0xe0dd, 0x4e550000u);
  EXPECT_NE(
      walkRefusal(file, kModality + pixels + offsets + fragment + longEnd)
          .find("element (fffe,e0dd) is a delimiter with a length of 1314193408 (a delimiter has none)"),
      std::string::npos);
  const std::string shortEnd = implicitElement(0xfffe, 0xe0dd, 2);
  EXPECT_NE(walkRefusal(file, kModality + pixels + offsets + fragment + shortEnd + "xx")
                .find("is a delimiter with a length of 2"),
            std::string::npos);
  // Outside pixel data GDCM only warns: a length the file holds is let through.
  const std::string sequenceEnd = implicitElement(0xfffe, 0xe0dd, 2);
  const std::string patientName = implicitElement(0x0010, 0x0010, 2, "AB");
  EXPECT_EQ(walkRefusal(file, kModality + kOpenSequence + kOpenItem + kModality + kItemEnd +
                                  sequenceEnd + patientName),
            "");
}

// A bare data set (no preamble, no meta group) in explicit VR: GDCM guesses its syntax from the
// VR after the first tag, and the walk reads it the same way (as implicit VR, its first VR and
// length bytes made a length of megabytes); the series then refuses it by what it is.
TEST_F(DicomFileWalkTest, ABareExplicitVrDataSetIsWalkedAsGdcmReadsIt) {
  const fs::path slice = series();
  test_support::recompressDicomSlice(slice, gdcm::TransferSyntax::ExplicitVRLittleEndian);
  const std::string bytes = fileBytes(slice);
  overwrite(slice, bytes.substr(metaGroupEnd(bytes)));
  gdcm::Reader reader;
  reader.SetFileName(slice.c_str());
  ASSERT_TRUE(reader.Read());
  ASSERT_EQ(reader.GetFile().GetHeader().GetDataSetTransferSyntax(),
            gdcm::TransferSyntax::ExplicitVRLittleEndian);
  const auto facts = walkDicomFile(dir_, slice);
  ASSERT_TRUE(facts.has_value());
  EXPECT_EQ(facts->seriesUid, kSeriesUid);
  EXPECT_TRUE(facts->hasPixelData);
  EXPECT_NE(refusal().find("slice IM2-4.dcm has no DICOM file meta header"), std::string::npos);
}

// Only SQ, UN, OB and OW elements may have an undefined length (PS3.5 7.1.3); GDCM's reader
// asserts on any other (a fuzzed slice's encapsulated pixel data as OF stopped the process).
TEST_F(DicomFileWalkTest, AnUndefinedLengthWithAnotherVrIsRefused) {
  const fs::path slice = series();
  test_support::recompressDicomSlice(slice, gdcm::TransferSyntax::JPEGLosslessProcess14_1);
  std::string bytes = fileBytes(slice);
  const std::string pixels = littleEndian(0x7fe0, 2) + littleEndian(0x0010, 2) + "OB";
  const std::size_t at = bytes.find(pixels);
  ASSERT_NE(at, std::string::npos);
  ASSERT_EQ(bytes.substr(at + 8, 4), littleEndian(0xffffffffu, 4));
  EXPECT_TRUE(walkDicomFile(dir_, slice).has_value());
  bytes.replace(at + 4, 2, "OF");
  overwrite(slice, bytes);
  EXPECT_NE(refusal().find("slice IM2-4.dcm: element (7fe0,0010) has an undefined length with VR OF"),
            std::string::npos);
}

// A private sequence stored as UN of undefined length (what a converter makes of a sequence whose
// tag it does not know) holds an implicit VR data set even in an explicit VR file (PS3.5 6.2.2):
// the walk reads its items so, and the series loads.
TEST_F(DicomFileWalkTest, AnUnknownSequenceInAnExplicitVrSliceIsWalkedAsImplicitVr) {
  const fs::path slice = series();
  for (const auto& file : fs::directory_iterator(dir_))
    test_support::recompressDicomSlice(file.path(), gdcm::TransferSyntax::ExplicitVRLittleEndian);
  std::string bytes = fileBytes(slice);
  // The first top-level element after group 0008 (explicit VR: 2- or 4-byte lengths by VR).
  std::size_t at = metaGroupEnd(bytes);
  while ((std::uint8_t(bytes[at]) | std::uint8_t(bytes[at + 1]) << 8) <= 0x0008) {
    const std::string vr = bytes.substr(at + 4, 2);
    const bool longForm = vr == "OB" || vr == "OW" || vr == "SQ" || vr == "UN" || vr == "UT";
    const auto number = [&](std::size_t from, int size) {
      std::uint32_t value = 0;
      for (int n = size - 1; n >= 0; --n) value = value << 8 | std::uint8_t(bytes[from + n]);
      return value;
    };
    at += longForm ? 12 + number(at + 8, 4) : 8 + number(at + 6, 2);
  }
  const std::string privateCreator =
      littleEndian(0x0009, 2) + littleEndian(0x0010, 2) + "LO" + littleEndian(8, 2) + "ANGIOTST";
  const std::string unknownSequence = littleEndian(0x0009, 2) + littleEndian(0x1010, 2) + "UN" +
                                      std::string(2, '\0') + littleEndian(0xffffffffu, 4);
  const std::string implicitItem = implicitElement(0xfffe, 0xe000, 0xffffffffu) +
                                   implicitElement(0x0008, 0x0100, 4, "ABCD") + kItemEnd;
  bytes.insert(at, privateCreator + unknownSequence + implicitItem + kSequenceEnd);
  overwrite(slice, bytes);
  EXPECT_EQ(refusal(), "");
  EXPECT_EQ(loaded_.volume.dims, glm::ivec3(16, 16, 4));
}

}  // namespace
}  // namespace angio
