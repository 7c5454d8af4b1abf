// Elements GDCM would assert on are refused by our walk before GDCM reads the slice, with one line
// naming the folder, the slice and the problem; slices as scanners write them (explicit and
// implicit VR little endian) and as our writer writes them still load. The slices are built in
// memory (tests/support/dicom_element_list.h) with one element changed.
#include "io/dicom_element_check.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>

#include "tests/support/dicom_element_list.h"
#include "tests/support/dicom_folder_test.h"
#include "tests/support/dicom_series_writer.h"
#include "tests/support/dicom_tag_patch.h"

namespace angio {
namespace {

using test_support::DicomTestElement;
using test_support::DicomTestSlice;
using test_support::dicomUnsignedShorts;

class DicomElementCheckTest : public test_support::DicomFolderTest {
 protected:
  // Three slices 1 mm apart, IM0..IM2; `change` rewrites the middle one (IM1.dcm).
  void series(bool explicitVr, const std::function<void(DicomTestSlice&)>& change = {}) {
    for (int k = 0; k < 3; ++k) {
      DicomTestSlice slice = test_support::ctTestSlice(k, explicitVr, k + 1);
      if (k == 1 && change) change(slice);
      slice.write(dir_ / ("IM" + std::to_string(k) + ".dcm"));
    }
  }
  // The refusal of a series whose middle slice `change` rewrote: names the slice and `problem`.
  void expectRefused(bool explicitVr, const std::function<void(DicomTestSlice&)>& change,
                     const std::string& problem) {
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    series(explicitVr, change);
    const std::string message = refusal();
    EXPECT_NE(message.find("slice IM1.dcm"), std::string::npos) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
  }
};

TEST_F(DicomElementCheckTest, ExplicitAndImplicitLittleEndianSlicesLoad) {
  for (const bool explicitVr : {true, false}) {
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    series(explicitVr);
    EXPECT_EQ(refusal(), "") << (explicitVr ? "explicit" : "implicit");
    EXPECT_EQ(loaded_.volume.dims, glm::ivec3(4, 4, 3));
  }
}

TEST_F(DicomElementCheckTest, OurWritersSlicesLoad) {
  test_support::writeDicomSeries(dir_, {0, 1, 2}, "1.2.826.0.1.3680043.2.1125.777.5", 3);
  EXPECT_EQ(refusal(), "");
}

TEST_F(DicomElementCheckTest, PixelModuleCountsNeedOneUnsignedShort) {
  expectRefused(
      true, [](DicomTestSlice& s) { s.set(0x0028, 0x0010, "SS", dicomUnsignedShorts({4})); },
      "element (0028,0010) has value representation SS where DICOM has one US value");
  expectRefused(
      true,
      [](DicomTestSlice& s) {
        s.set(0x0028, 0x0100, "US", dicomUnsignedShorts({16, 16}));
      },
      "element (0028,0100) has a value of 4 bytes where DICOM has one US value");
  expectRefused(
      false,
      [](DicomTestSlice& s) {
        s.set(0x0028, 0x0002, "US", dicomUnsignedShorts({1, 1}));
      },
      "element (0028,0002) has a value of 4 bytes where DICOM has one US value");
}

TEST_F(DicomElementCheckTest, NumbersNeedTheDictionarysRepresentationAndWholeValues) {
  expectRefused(
      true, [](DicomTestSlice& s) { s.set(0x0028, 0x0120, "FL", std::string(4, '\0')); },
      "element (0028,0120) has value representation FL where DICOM has US or SS");
  expectRefused(
      true, [](DicomTestSlice& s) { s.set(0x0018, 0x9087, "FD", std::string(4, '\0')); },
      "element (0018,9087) has a value of 4 bytes, not a whole number of 8-byte values");
}

TEST_F(DicomElementCheckTest, SequencesOnlyWhereDicomHasThem) {
  expectRefused(
      true,
      [](DicomTestSlice& s) {
        s.set({0x0008, 0x0060, "SQ", test_support::emptySequenceValue(), true});
      },
      "element (0008,0060) is a sequence where DICOM has a value (CS)");
  expectRefused(
      true, [](DicomTestSlice& s) { s.set(0x0008, 0x1140, "LO", "IMAGE"); },
      "element (0008,1140) has a value (LO) where DICOM has a sequence");
  expectRefused(
      false,
      [](DicomTestSlice& s) {
        s.set({0x0008, 0x0060, "", test_support::emptySequenceValue(), true});
      },
      "element (0008,0060) has an undefined length where DICOM has a value");
}

TEST_F(DicomElementCheckTest, ValueRepresentationsGdcmCannotShowAreRefused) {
  for (const char* vr : {"OD", "OL", "OV", "SV", "UV"})
    expectRefused(
        true,
        [&](DicomTestSlice& s) {
          s.set(0x0009, 0x0010, "LO", "ACME").set(0x0009, 0x1001, vr, std::string(8, '\0'));
        },
        std::string("element (0009,1001) has value representation ") + vr + ", which is not read");
}

TEST_F(DicomElementCheckTest, APrivateCreatorEncodedAsASequenceIsRefused) {
  expectRefused(
      true,
      [](DicomTestSlice& s) {
        s.set({0x0009, 0x0010, "SQ", test_support::emptySequenceValue(), true});
      },
      "element (0009,0010) is a private creator encoded as a sequence");
}

TEST_F(DicomElementCheckTest, ImplicitUsOrSsBeforePixelRepresentationIsRefused) {
  expectRefused(
      false,
      [](DicomTestSlice& s) {
        s.remove(0x0028, 0x0103).set(0x0028, 0x0120, "US", dicomUnsignedShorts({0}));
      },
      "element (0028,0120) is US or SS in implicit VR before PixelRepresentation");
}

TEST_F(DicomElementCheckTest, WaveformsMultiFrameAndOtherSopClassesAreRefused) {
  expectRefused(
      true,
      [](DicomTestSlice& s) {
        s.set({0x5400, 0x0100, "SQ", test_support::emptySequenceValue(), true});
      },
      "slice IM1.dcm has waveform data (5400), which is not read");
  expectRefused(
      true, [](DicomTestSlice& s) { s.set(0x0008, 0x0016, "UI", "1.2.840.10008.5.1.4.1.1.2.1"); },
      "is of SOP class '1.2.840.10008.5.1.4.1.1.2.1', not a single-frame");
  expectRefused(
      true, [](DicomTestSlice& s) { s.set(0x0002, 0x0002, "UI", "1.2.840.10008.5.1.4.1.1.6.1"); },
      "is of SOP class '1.2.840.10008.5.1.4.1.1.6.1', not a single-frame");
  expectRefused(
      true, [](DicomTestSlice& s) { s.set(0x0008, 0x0016, "UI", "1.2.840.10008.5.1.4.1.1.481.2"); },
      "is of SOP class '1.2.840.10008.5.1.4.1.1.481.2'");
  expectRefused(
      true, [](DicomTestSlice& s) { s.set(0x0028, 0x0008, "IS", "2"); },
      "has NumberOfFrames (0028,0008) '2'; need single-frame slices");
  expectRefused(
      true, [](DicomTestSlice& s) { s.set(0x0028, 0x0005, "US", dicomUnsignedShorts({3})); },
      "has ImageDimensions (0028,0005) 3; need 2-D slices");
}

TEST_F(DicomElementCheckTest, AnUnknownTransferSyntaxIsRefused) {
  expectRefused(
      true, [](DicomTestSlice& s) { s.set(0x0002, 0x0010, "UI", "1.2.3.4"); },
      "slice IM1.dcm: its data set has transfer syntax '1.2.3.4', which is not read");
}

// GDCM's image reader asserts that a RecognitionCode starts like ACR-NEMA's (the saved findings
// dicom_series/gdcm-acr-nema-*); ACR-NEMA's own still load.
TEST_F(DicomElementCheckTest, RecognitionCodesMustBeAcrNemas) {
  for (const bool explicitVr : {true, false})
    expectRefused(
        explicitVr, [](DicomTestSlice& s) { s.set(0x0008, 0x0010, "SH", "154123.116775"); },
        "has a RecognitionCode (0008,0010) '154123.116775' that is not ACR-NEMA's");
  std::filesystem::remove_all(dir_);
  std::filesystem::create_directories(dir_);
  series(true, [](DicomTestSlice& s) { s.set(0x0008, 0x0010, "SH", "ACR-NEMA 2.0"); });
  EXPECT_EQ(refusal(), "");
}

// GDCM keeps the first of two equal tags and sorts the others: the walk would check other values.
TEST_F(DicomElementCheckTest, ElementsOutOfOrderAreRefused) {
  expectRefused(
      true,
      [](DicomTestSlice& s) {
        s.append({0x0010, 0x0010, "PN", "DOE^JOHN"});
      },
      "element (0010,0010) is out of order (tags must ascend)");
}

// A value's control characters are escaped, so the message stays one line (a fuzz finding).
TEST_F(DicomElementCheckTest, ValuesInMessagesAreShownOnOneLine) {
  expectRefused(
      true, [](DicomTestSlice& s) { s.set(0x0028, 0x0004, "CS", "MONOCHRO\rE1"); },
      "has PhotometricInterpretation (0028,0004) 'MONOCHRO\\x0dE1'");
}

TEST_F(DicomElementCheckTest, ElementProblemsAreEmptyForWellFormedElements) {
  EXPECT_EQ(dicomElementProblem({0x0028, 0x0010, "US", 2}, dicomUnsignedShorts({512})), "");
  EXPECT_EQ(dicomElementProblem({0x0028, 0x0010, "", 2}, dicomUnsignedShorts({512})), "");
  EXPECT_EQ(dicomElementProblem({0x0008, 0x1140, "SQ", kDicomUndefinedLength}, ""), "");
  EXPECT_EQ(dicomElementProblem({0x7fe0, 0x0010, "OB", kDicomUndefinedLength}, ""), "");
  EXPECT_EQ(dicomElementProblem({0x0029, 0x1010, "UN", 7}, "abcdefg"), "");
  EXPECT_EQ(dicomImageProblem({0x0008, 0x0010, "LO", 12}, "ACRNEMA_LIBIDO"), "");
  EXPECT_EQ(dicomTransferSyntaxProblem("1.2.840.10008.1.2.4.70"), "");
}

}  // namespace
}  // namespace angio
