// DICOM person names, dates and padding made readable for the banner (io/study_info.h).
#include "io/study_info.h"

#include <gtest/gtest.h>

namespace angio {
namespace {

TEST(StudyInfo, PersonNamesReadFamilyCommaGivenMiddleFromTheAlphabeticForm) {
  EXPECT_EQ(readablePersonName("DOE^JANE"), "DOE, JANE");
  EXPECT_EQ(readablePersonName("DOE^JANE^Q^DR^JR "), "DOE, JANE Q");  // prefix, suffix left out
  EXPECT_EQ(readablePersonName("DOE"), "DOE");
  EXPECT_EQ(readablePersonName("^JANE"), "JANE");
  EXPECT_EQ(readablePersonName("YAMADA^TARO=山田^太郎=やまだ^たろう"), "YAMADA, TARO");
  EXPECT_EQ(readablePersonName(""), "");
  EXPECT_EQ(readablePersonName("Anonymized"), "Anonymized");
}

TEST(StudyInfo, DatesReadAsIsoAndOthersStayAsTheyAre) {
  EXPECT_EQ(readableDate("20240301"), "2024-03-01");
  EXPECT_EQ(readableDate("20240301 "), "2024-03-01");
  EXPECT_EQ(readableDate("2024.03.01"), "2024.03.01");  // an old (ACR-NEMA) form, shown as it is
  EXPECT_EQ(readableDate(""), "");
}

TEST(StudyInfo, PaddingIsTrimmedAndEmptyMeansNoTags) {
  EXPECT_EQ(trimmedDicomValue(" CTA Aorta "), "CTA Aorta");
  EXPECT_EQ(trimmedDicomValue(std::string("CT\0", 3)), "CT");
  EXPECT_EQ(trimmedDicomValue("   "), "");
  EXPECT_TRUE(StudyInfo{}.empty());
  EXPECT_FALSE((StudyInfo{"", "", "", "", "CT"}).empty());
}

}  // namespace
}  // namespace angio
