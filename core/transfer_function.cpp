#include "core/transfer_function.h"

#include <algorithm>

namespace angio {

void sortPoints(TransferFunction& tf) {
  std::stable_sort(tf.points.begin(), tf.points.end(),
                   [](const ControlPoint& a, const ControlPoint& b) { return a.hu < b.hu; });
}

namespace {

glm::vec4 pointValue(const ControlPoint& p) { return glm::vec4(p.color, float(p.opacity)); }

glm::vec4 interpolate(const std::vector<ControlPoint>& points, double hu) {
  if (points.empty()) return glm::vec4(0.f);
  if (hu <= points.front().hu) return pointValue(points.front());
  if (hu >= points.back().hu) return pointValue(points.back());
  const auto upper = std::upper_bound(points.begin(), points.end(), hu,
                                      [](double h, const ControlPoint& p) { return h < p.hu; });
  const ControlPoint& b = *upper;
  const ControlPoint& a = *(upper - 1);
  const double t = (hu - a.hu) / (b.hu - a.hu);
  return glm::mix(pointValue(a), pointValue(b), float(t));
}

}  // namespace

glm::vec4 evaluate(const TransferFunction& tf, double hu) {
  glm::vec4 value = interpolate(tf.points, hu - tf.modulators.huShift);
  value.a = float(std::clamp(value.a * tf.modulators.opacityScale, 0.0, 1.0));
  return value;
}

TfTable buildTable(const TransferFunction& tf) {
  TfTable table;
  TransferFunction sorted = tf;
  sortPoints(sorted);
  for (int d = 0; d < kDensityLevels; ++d) {
    table.rgba[d] = evaluate(sorted, huOfDensity(d));
    table.integratedOpacity[d + 1] = table.integratedOpacity[d] + table.rgba[d].a;
    table.integratedVisible[d + 1] = table.integratedVisible[d] + (table.rgba[d].a > 0.f ? 1 : 0);
  }
  return table;
}

TfTable visibilityUnion(const std::vector<const TfTable*>& tables) {
  TfTable any;
  for (int d = 0; d < kDensityLevels; ++d) {
    bool visible = false;
    for (const TfTable* table : tables) visible = visible || (table && table->rgba[d].a > 0.f);
    any.integratedVisible[d + 1] = any.integratedVisible[d] + (visible ? 1 : 0);
  }
  return any;
}

}  // namespace angio
