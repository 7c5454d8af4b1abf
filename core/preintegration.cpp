#include "core/preintegration.h"

#include <algorithm>
#include <cmath>

namespace angio {

PreintegratedTable::PreintegratedTable(const TfTable& table, double osd)
    : osd_(osd), post_(correctedTable(table, osd)), entries_(kDensityLevels + 1),
      visibleBelow_(table.integratedVisible) {
  for (int d = 0; d < kDensityLevels; ++d) {
    Entry& entry = entries_[d];
    entry.tau = extinctionPerVoxel(table.rgba[d].a);
    entry.emission = glm::dvec3(table.rgba[d]) * entry.tau;
    entries_[d + 1].tauBelow = entry.tauBelow + entry.tau;
    entries_[d + 1].emissionBelow = entry.emissionBelow + entry.emission;
  }
}

glm::vec4 PreintegratedTable::within(int entry, double length) const {
  const glm::vec4 post = post_[entry];
  if (post.a <= 0.f) return glm::vec4(0.f);
  return glm::vec4(glm::vec3(post), 1.f - float(std::exp(-length * entries_[entry].tau)));
}

glm::vec4 PreintegratedTable::crossing(float front, float back, int f, int b, double length) const {
  if (visibleBelow_[std::max(f, b) + 1] - visibleBelow_[std::min(f, b)] == 0) return glm::vec4(0.f);
  // The integrals from density -0.5 up to each end: an entry holds for densities within half a
  // unit of it, so an end's position in its entry is s - d + 0.5.
  const Entry& ef = entries_[f];
  const Entry& eb = entries_[b];
  const double uf = double(front) - f + 0.5, ub = double(back) - b + 0.5;
  const double tauSum = (eb.tauBelow + ub * eb.tau) - (ef.tauBelow + uf * ef.tau);
  // Only the differences need doubles; the rest is float (a division and a reciprocal).
  const float integral = float(tauSum), meanTau = integral / (back - front);
  // Visible entries met only at a boundary: nothing on the way absorbs or emits.
  if (!(meanTau > 0.f)) return glm::vec4(0.f);
  const glm::dvec3 emitted =
      (eb.emissionBelow + ub * eb.emission) - (ef.emissionBelow + uf * ef.emission);
  const glm::vec3 rgb = glm::clamp(glm::vec3(emitted) * (1.f / integral), 0.f, 1.f);
  return glm::vec4(rgb, 1.f - std::exp(-float(length) * meanTau));
}

PreintegratedTables preintegratedTables(const RegionTables& tables, double osd) {
  PreintegratedTables frame;
  if (tables.regions && tables.focus) frame.focus = PreintegratedTable(*tables.focus, osd);
  if (tables.regions && tables.context) frame.context = PreintegratedTable(*tables.context, osd);
  if (tables.outside) frame.outside = PreintegratedTable(*tables.outside, osd);
  for (int label = 0; tables.labels && label < kLabelCount; ++label)
    if (const TfTable* own = tables.labels->ownTf(label)) frame.ownTables.emplace_back(*own, osd);
  return frame;
}

}  // namespace angio
