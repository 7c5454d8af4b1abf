// The banner's lines from a series' patient and study tags (gui/study_banner.h).
#include "gui/study_banner.h"

#include <gtest/gtest.h>

namespace angio {
namespace {

using Lines = std::vector<std::string>;

TEST(StudyBanner, WhoThenWhatAndMissingTagsLeaveNoGaps) {
  const StudyInfo full{"DOE, JANE", "PAT-0042", "2024-03-01", "CTA Aorta", "CT"};
  EXPECT_EQ(studyBanner(full), (Lines{"DOE, JANE   ID PAT-0042", "2024-03-01   CTA Aorta   CT"}));
  EXPECT_EQ(studyBanner({"", "PAT-0042", "", "", "CT"}), (Lines{"ID PAT-0042", "CT"}));
  EXPECT_EQ(studyBanner({"", "", "2024-03-01", "", ""}), (Lines{"2024-03-01"}));
  EXPECT_EQ(studyBanner({}), Lines{});  // NRRD, MetaImage: no banner
}

}  // namespace
}  // namespace angio
