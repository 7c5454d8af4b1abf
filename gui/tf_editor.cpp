#include "gui/tf_editor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/voxel.h"

namespace angio {

namespace {

constexpr double kMinHu = -1024, kMaxHu = 3071;
constexpr float kPlotHeight = 170, kColorBarHeight = 14, kTickHeight = 16;
constexpr float kPickRadius = 7;

struct PlotFrame {
  ImVec2 min, max;
  double huMin, huMax;

  float width() const { return max.x - min.x; }
  float height() const { return max.y - min.y; }
  float xOfHu(double hu) const { return min.x + float((hu - huMin) / (huMax - huMin)) * width(); }
  float yOfOpacity(double opacity) const { return max.y - float(opacity) * height(); }
  double huOfX(float x) const { return huMin + double(x - min.x) / width() * (huMax - huMin); }
  double opacityOfY(float y) const { return std::clamp(double(max.y - y) / height(), 0.0, 1.0); }
};

ImU32 colorOf(const glm::vec3& rgb, float alpha = 1.f) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(rgb.r, rgb.g, rgb.b, alpha));
}

TransferFunction withoutModulators(const TransferFunction& tf) {
  TransferFunction raw = tf;
  raw.modulators = {};
  return raw;
}

// Where the points are drawn: their HU moved by the shift, so they sit over the histogram's
// densities they color; opacity unscaled (the scaled curve is drawn faintly).
ImVec2 pointPosition(const PlotFrame& plot, const TransferFunction& tf, const ControlPoint& point) {
  return ImVec2(plot.xOfHu(point.hu + tf.modulators.huShift), plot.yOfOpacity(point.opacity));
}

int pointUnderMouse(const PlotFrame& plot, const TransferFunction& tf, ImVec2 mouse) {
  int best = -1;
  float bestDistance = kPickRadius * kPickRadius;
  for (int n = 0; n < int(tf.points.size()); ++n) {
    const ImVec2 p = pointPosition(plot, tf, tf.points[n]);
    const float d = (p.x - mouse.x) * (p.x - mouse.x) + (p.y - mouse.y) * (p.y - mouse.y);
    if (d <= bestDistance) best = n, bestDistance = d;
  }
  return best;
}

double niceStep(double range, int targetTicks) {
  const double raw = range / std::max(targetTicks, 1);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double step : {1.0, 2.0, 5.0, 10.0})
    if (step * power >= raw) return step * power;
  return 10 * power;
}

void drawHistogram(ImDrawList* draw, const PlotFrame& plot, const std::vector<float>& histogram) {
  if (histogram.empty()) return;
  const int columns = std::max(1, int(plot.width()));
  for (int column = 0; column < columns; ++column) {
    const int first = densityOfHu(plot.huOfX(plot.min.x + column));
    const int last = std::max(first, densityOfHu(plot.huOfX(plot.min.x + column + 1)) - 1);
    float value = 0;
    for (int d = first; d <= last; ++d) value = std::max(value, histogram[d]);
    if (value <= 0) continue;
    const float x = plot.min.x + column;
    draw->AddRectFilled(ImVec2(x, plot.max.y - value * plot.height()), ImVec2(x + 1, plot.max.y),
                        IM_COL32(90, 90, 100, 255));
  }
}

void drawCurves(ImDrawList* draw, const PlotFrame& plot, const TransferFunction& tf, int selected) {
  // The effective opacity (modulators applied), sampled per pixel column.
  if (tf.modulators.opacityScale != 1.0 || tf.modulators.huShift != 0.0) {
    ImVec2 previous;
    for (int column = 0; column <= int(plot.width()); ++column) {
      const float x = plot.min.x + column;
      const ImVec2 p(x, plot.yOfOpacity(std::min(1.0, double(evaluate(tf, plot.huOfX(x)).a))));
      if (column > 0) draw->AddLine(previous, p, IM_COL32(255, 255, 255, 90), 1);
      previous = p;
    }
  }
  for (std::size_t n = 1; n < tf.points.size(); ++n) {
    draw->AddLine(pointPosition(plot, tf, tf.points[n - 1]), pointPosition(plot, tf, tf.points[n]),
                  IM_COL32(235, 235, 235, 255), 1.5f);
  }
  for (int n = 0; n < int(tf.points.size()); ++n) {
    const ImVec2 p = pointPosition(plot, tf, tf.points[n]);
    draw->AddCircleFilled(p, 5, colorOf(tf.points[n].color));
    draw->AddCircle(p, 5.5f, n == selected ? IM_COL32(255, 220, 0, 255) : IM_COL32(255, 255, 255, 200),
                    0, n == selected ? 2.f : 1.f);
  }
}

void drawColorBar(ImDrawList* draw, const PlotFrame& plot, const TransferFunction& tf, float top) {
  for (int column = 0; column < int(plot.width()); ++column) {
    const float x = plot.min.x + column;
    const glm::vec4 rgba = evaluate(tf, plot.huOfX(x + 0.5f));
    draw->AddRectFilled(ImVec2(x, top), ImVec2(x + 1, top + kColorBarHeight), colorOf(glm::vec3(rgba)));
  }
}

void drawTicks(ImDrawList* draw, const PlotFrame& plot, float top) {
  for (const HuTick& tick : huTicks(plot.huMin, plot.huMax)) {
    const float x = plot.xOfHu(tick.hu);
    draw->AddLine(ImVec2(x, top), ImVec2(x, top + 4), IM_COL32(200, 200, 200, 255));
    const float w = ImGui::CalcTextSize(tick.label.c_str()).x;
    draw->AddText(ImVec2(std::clamp(x - w / 2, plot.min.x, plot.max.x - w), top + 3),
                  IM_COL32(200, 200, 200, 255), tick.label.c_str());
  }
}

// Mouse on the plot: pick, drag, add, delete, zoom the HU range.
void interactWithPlot(const PlotFrame& plot, TransferFunction& tf, TfEditorView& view, bool& changed) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool hovered = ImGui::IsItemHovered();
  const int under = hovered ? pointUnderMouse(plot, tf, io.MousePos) : -1;
  if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && under < 0) {
    ControlPoint point;
    point.hu = std::clamp(plot.huOfX(io.MousePos.x) - tf.modulators.huShift, kMinHu, kMaxHu);
    point.opacity = plot.opacityOfY(io.MousePos.y);
    point.color = glm::vec3(evaluate(withoutModulators(tf), point.hu));
    tf.points.push_back(point);
    sortPoints(tf);
    view.selected = int(std::find_if(tf.points.begin(), tf.points.end(),
                                     [&](const ControlPoint& p) {
                                       return p.hu == point.hu && p.opacity == point.opacity;
                                     }) -
                        tf.points.begin());
    changed = true;
  } else if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    view.selected = under;
    view.dragging = under;
    if (under >= 0)
      view.drag = {{io.MousePos.x, io.MousePos.y}, tf.points[under].hu, tf.points[under].opacity};
  }
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right) && under >= 0 && tf.points.size() > 1) {
    tf.points.erase(tf.points.begin() + under);
    view.selected = view.dragging = -1;
    changed = true;
  }
  if (view.dragging >= 0 && view.dragging < int(tf.points.size()) &&
      ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    // Points keep their order: a point stops at its neighbours' HU.
    const int n = view.dragging;
    const double lo = n > 0 ? tf.points[n - 1].hu : kMinHu;
    const double hi = n + 1 < int(tf.points.size()) ? tf.points[n + 1].hu : kMaxHu;
    const HuOpacity moved = followDrag(view.drag, {io.MousePos.x, io.MousePos.y}, io.KeyShift,
                                       (plot.huMax - plot.huMin) / plot.width(), 1.0 / plot.height());
    ControlPoint& point = tf.points[n];
    const ControlPoint before = point;
    point.hu = std::clamp(moved.hu, lo, hi);
    point.opacity = std::clamp(moved.opacity, 0.0, 1.0);
    changed = changed || point != before;
  } else {
    view.dragging = -1;
  }
  // Ctrl: ImGui does not scroll the window on Ctrl+wheel, so the plot stays under the pointer.
  if (hovered && io.MouseWheel != 0 && io.KeyCtrl) {
    const double hu = plot.huOfX(io.MousePos.x), scale = std::pow(0.8, double(io.MouseWheel));
    view.huMin = std::max(kMinHu, hu - (hu - view.huMin) * scale);
    view.huMax = std::min(kMaxHu, hu + (view.huMax - hu) * scale);
    if (view.huMax - view.huMin < 20) view.huMax = view.huMin + 20;
  }
}

void drawSelectedPointFields(TransferFunction& tf, TfEditorView& view, bool& changed) {
  if (view.selected < 0 || view.selected >= int(tf.points.size())) {
    // Two rows, as the selected point's fields: the controls below do not move on a click.
    ImGui::TextDisabled("Click a point: edit; double-click: add; right-click: delete.");
    ImGui::TextDisabled("Shift-drag: along one axis; Ctrl+wheel: zoom the HU axis.");
    return;
  }
  ControlPoint& point = tf.points[view.selected];
  ImGui::PushID(view.selected);
  float rgb[3] = {point.color.r, point.color.g, point.color.b};
  if (ImGui::ColorEdit3("color", rgb, ImGuiColorEditFlags_Float)) {
    point.color = glm::clamp(glm::vec3(rgb[0], rgb[1], rgb[2]), 0.f, 1.f);
    changed = true;
  }
  // The HU the point is drawn at and colors: its own moved by the HU shift.
  const int n = view.selected;
  const double shift = tf.modulators.huShift;
  const double lo = (n > 0 ? tf.points[n - 1].hu : kMinHu) + shift;
  const double hi = (n + 1 < int(tf.points.size()) ? tf.points[n + 1].hu : kMaxHu) + shift;
  double shown = point.hu + shift;
  ImGui::SetNextItemWidth(120);
  if (ImGui::DragScalar("HU", ImGuiDataType_Double, &shown, 1.0f, &lo, &hi, "%.0f")) {
    point.hu = std::clamp(shown, lo, hi) - shift;
    changed = true;
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  const double zero = 0, one = 1;
  if (ImGui::SliderScalar("opacity", ImGuiDataType_Double, &point.opacity, &zero, &one, "%.3f",
                          ImGuiSliderFlags_AlwaysClamp))
    changed = true;
  ImGui::PopID();
}

void drawModulators(TransferFunction& tf, TfEditorView& view, bool& changed) {
  const double scaleMin = 0, scaleMax = 3, shiftMin = -500, shiftMax = 500;
  ImGui::SetNextItemWidth(180);
  if (ImGui::SliderScalar("opacity modulator", ImGuiDataType_Double, &tf.modulators.opacityScale,
                          &scaleMin, &scaleMax, "x %.2f", ImGuiSliderFlags_AlwaysClamp))
    changed = true;
  ImGui::SetNextItemWidth(180);
  if (ImGui::SliderScalar("HU shift", ImGuiDataType_Double, &tf.modulators.huShift, &shiftMin, &shiftMax,
                          "%+.0f HU", ImGuiSliderFlags_AlwaysClamp))
    changed = true;
  if (ImGui::SmallButton("reset modulators") &&
      (tf.modulators.opacityScale != 1 || tf.modulators.huShift != 0)) {
    tf.modulators = {};
    changed = true;
  }
  ImGui::SameLine();
  if (ImGui::SmallButton("full HU range")) view.huMin = kMinHu, view.huMax = kMaxHu;
}

}  // namespace

std::vector<HuTick> huTicks(double huMin, double huMax) {
  std::vector<HuTick> ticks;
  const double step = niceStep(huMax - huMin, 6);
  // Whole multiples of the step: no rounding builds up, and 0 is +0 ("-0" from ceil(-0.3) * step).
  for (long k = long(std::ceil(huMin / step)); double(k) * step <= huMax; ++k) {
    const double hu = k == 0 ? 0.0 : double(k) * step;
    char label[16];
    std::snprintf(label, sizeof label, "%.0f", hu);
    ticks.push_back({hu, label});
  }
  return ticks;
}

HuOpacity followDrag(TfPointDrag& drag, glm::vec2 pointer, bool oneAxis, double huPerPx,
                     double opacityPerPx) {
  const glm::vec2 motion = pointer - drag.pressedAt;
  drag.huFollows = drag.huFollows || std::abs(motion.x) > kTfDragDeadZonePx;
  drag.opacityFollows = drag.opacityFollows || std::abs(motion.y) > kTfDragDeadZonePx;
  bool huMoves = drag.huFollows, opacityMoves = drag.opacityFollows;
  if (oneAxis) {
    const bool sideways = std::abs(motion.x) >= std::abs(motion.y);
    huMoves = huMoves && sideways;
    opacityMoves = opacityMoves && !sideways;
  }
  HuOpacity moved{drag.hu, drag.opacity};
  if (huMoves) moved.hu = std::round(drag.hu + double(motion.x) * huPerPx);
  if (opacityMoves) moved.opacity = drag.opacity - double(motion.y) * opacityPerPx;
  return moved;
}

std::vector<float> logHistogram(const DensityHistogram& histogram) {
  std::vector<float> result(histogram.size());
  float largest = 0;
  for (std::size_t d = 0; d < histogram.size(); ++d) {
    result[d] = float(std::log1p(double(histogram[d])));
    largest = std::max(largest, result[d]);
  }
  if (largest > 0)
    for (float& value : result) value /= largest;
  return result;
}

TfEdit drawTfEditor(const TransferFunction& input, const std::vector<float>& histogram,
                    TfEditorView& view) {
  TfEdit edit;
  edit.tf = input;
  TransferFunction& tf = edit.tf;
  bool changed = false;

  const float width = std::max(ImGui::GetContentRegionAvail().x, 100.f);
  const ImVec2 min = ImGui::GetCursorScreenPos();
  const PlotFrame plot{min, ImVec2(min.x + width, min.y + kPlotHeight), view.huMin, view.huMax};
  view.plotMin = plot.min;
  view.plotMax = plot.max;
  ImGui::InvisibleButton("tf plot", ImVec2(width, kPlotHeight),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  interactWithPlot(plot, tf, view, changed);

  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(plot.min, ImVec2(plot.max.x, plot.max.y + kColorBarHeight + kTickHeight + 4), true);
  draw->AddRectFilled(plot.min, plot.max, IM_COL32(25, 25, 30, 255));
  drawHistogram(draw, plot, histogram);
  drawCurves(draw, plot, tf, view.selected);
  draw->AddRect(plot.min, plot.max, IM_COL32(120, 120, 120, 255));
  drawColorBar(draw, plot, tf, plot.max.y + 2);
  drawTicks(draw, plot, plot.max.y + kColorBarHeight + 2);
  draw->PopClipRect();
  ImGui::Dummy(ImVec2(width, kColorBarHeight + kTickHeight + 4));
  if (histogram.empty()) ImGui::TextDisabled("histogram: counting...");

  drawSelectedPointFields(tf, view, changed);
  drawModulators(tf, view, changed);

  edit.changed = changed && tf != input;
  if (edit.changed && !view.gestureBefore) view.gestureBefore = input;
  const bool holding = view.dragging >= 0 || ImGui::IsAnyItemActive();
  if (!holding && view.gestureBefore) {
    edit.committedBefore = std::move(view.gestureBefore);
    view.gestureBefore.reset();
  }
  return edit;
}

void TfHistory::push(const TransferFunction& before) {
  undo_.push_back(before);
  if (undo_.size() > kLimit) undo_.erase(undo_.begin());
  redo_.clear();
}

std::optional<TransferFunction> TfHistory::undo(const TransferFunction& current) {
  if (undo_.empty()) return std::nullopt;
  TransferFunction previous = std::move(undo_.back());
  undo_.pop_back();
  redo_.push_back(current);
  return previous;
}

std::optional<TransferFunction> TfHistory::redo(const TransferFunction& current) {
  if (redo_.empty()) return std::nullopt;
  TransferFunction next = std::move(redo_.back());
  redo_.pop_back();
  undo_.push_back(current);
  return next;
}

}  // namespace angio
