#pragma once
// The patient and study banner over the 3-D view and in the Data section: who (name, ID) on the
// first line, what (date, series description, modality) on the second; lines without any tag
// are left out, so a dataset without tags shows none.
#include <string>
#include <vector>

#include "io/study_info.h"

namespace angio {

std::vector<std::string> studyBanner(const StudyInfo& study);

}  // namespace angio
