#include "core/compositing.h"

namespace angio {

float opacityAtDistance(float opacityPerVoxel, double osd) {
  return float(1.0 - std::pow(1.0 - double(opacityPerVoxel), osd));
}

double extinctionPerVoxel(float opacityPerVoxel) {
  return std::min(-std::log1p(-std::min(double(opacityPerVoxel), 1.0)), kMaxExtinction);
}

SampleTable correctedTable(const TfTable& table, double osd) {
  SampleTable corrected;
  for (int d = 0; d < kDensityLevels; ++d) {
    corrected[d] = table.rgba[d];
    corrected[d].a = opacityAtDistance(table.rgba[d].a, osd);
  }
  return corrected;
}

FrameTables frameTables(const RegionTables& tables, double osd) {
  FrameTables frame;
  if (tables.regions && tables.focus)
    frame.focus = correctedTable(*tables.focus, osd), frame.hasFocus = true;
  if (tables.regions && tables.context)
    frame.context = correctedTable(*tables.context, osd), frame.hasContext = true;
  if (tables.outside) frame.outside = correctedTable(*tables.outside, osd), frame.hasOutside = true;
  frame.ownSlot.fill(-1);
  for (int label = 0; tables.labels && label < kLabelCount; ++label)
    if (const TfTable* own = tables.labels->ownTf(label)) {
      frame.ownSlot[label] = int(frame.ownTables.size());
      frame.ownTables.push_back(correctedTable(*own, osd));
    }
  return frame;
}

glm::vec4 mipPixel(float maximumDensity, const MipWindow& window) {
  const double low = window.level - window.window / 2;
  const float grey = float(std::clamp((huOfDensity(maximumDensity) - low) / window.window, 0.0, 1.0));
  return glm::vec4(grey, grey, grey, 1.f);
}

}  // namespace angio
