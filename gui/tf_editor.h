#pragma once
// The transfer-function editor (immediate mode): drawn every frame from a TransferFunction value,
// returns the edited value; the app decides what an edit triggers (a progressive render, an undo
// step; while a gesture is held ImGui reports an active item and the app renders fast only). Plot: the volume's density histogram (log counts) behind the opacity curve, control points
// colored by their color; drag a point to move it (HU and opacity: each once the pointer has left
// a small dead zone along it; Shift moves along one axis), double-click to add one, right-click to
// delete one, Ctrl+wheel to zoom the HU range (the plain wheel scrolls the panel). Below: the color bar, HU ticks, the
// selected point's fields, and the thesis's safe manipulators (opacity modulator, HU shift).
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <imgui.h>

#include "core/transfer_function.h"
#include "core/volume.h"

namespace angio {

// A point's drag as it was pressed: the pointer and the point then, and which axes follow the
// pointer (each once the pointer has moved past the dead zone along it, so a sideways drag with a
// pixel of slip keeps the opacity, and the other way round).
struct TfPointDrag {
  glm::vec2 pressedAt{0.f};
  double hu = 0, opacity = 0;
  bool huFollows = false, opacityFollows = false;
  friend bool operator==(const TfPointDrag&, const TfPointDrag&) = default;
};
inline constexpr float kTfDragDeadZonePx = 3;

struct HuOpacity {
  double hu = 0, opacity = 0;
  friend bool operator==(const HuOpacity&, const HuOpacity&) = default;
};
// The dragged point for the pointer at `pointer`: `huPerPx` and `opacityPerPx` are the plot's
// scales (opacity grows upwards, screen y downwards); `oneAxis` (Shift held) moves the point along
// the dominant axis of the motion only. HU is rounded to whole HU; neither is clamped here.
HuOpacity followDrag(TfPointDrag& drag, glm::vec2 pointer, bool oneAxis, double huPerPx,
                     double opacityPerPx);

// The HU axis's ticks between huMin and huMax (about six, at 1, 2 or 5 times a power of ten),
// each with its label ("0", never "-0").
struct HuTick {
  double hu = 0;
  std::string label;
};
std::vector<HuTick> huTicks(double huMin, double huMax);

struct TfEditorView {
  double huMin = -1024, huMax = 3071;  // the visible HU range
  int selected = -1;                   // index of the selected point
  int dragging = -1;                   // index of the point being dragged
  TfPointDrag drag;                    // of `dragging`
  // The TF before the edit gesture in progress (a drag, a slider held, a color being picked).
  std::optional<TransferFunction> gestureBefore;
  ImVec2 plotMin, plotMax;  // where the plot was drawn last frame (screen)
};

struct TfEdit {
  TransferFunction tf;
  bool changed = false;  // tf differs from the input
  // Set when a gesture ended: the TF before it (one undo step).
  std::optional<TransferFunction> committedBefore;
};

// log(1 + count) per density, scaled to [0, 1] over all densities; empty = not ready.
std::vector<float> logHistogram(const DensityHistogram& histogram);

TfEdit drawTfEditor(const TransferFunction& tf, const std::vector<float>& histogram, TfEditorView& view);

// Undo/redo of TF edits: push the TF before each edit.
class TfHistory {
 public:
  void push(const TransferFunction& before);
  // Returns the TF to go back/forward to (and records `current` on the other stack).
  std::optional<TransferFunction> undo(const TransferFunction& current);
  std::optional<TransferFunction> redo(const TransferFunction& current);
  bool canUndo() const { return !undo_.empty(); }
  bool canRedo() const { return !redo_.empty(); }

 private:
  static constexpr std::size_t kLimit = 200;
  std::vector<TransferFunction> undo_, redo_;
};

}  // namespace angio
