#pragma once
// The transfer-function editor (immediate mode): drawn every frame from a TransferFunction value,
// returns the edited value; the app decides what an edit triggers (a progressive render, an undo
// step; while a gesture is held ImGui reports an active item and the app renders fast only). Plot: the volume's density histogram (log counts) behind the opacity curve, control points
// colored by their color; drag a point to move it (HU and opacity), double-click to add one,
// right-click to delete one, wheel to zoom the HU range. Below: the color bar, HU ticks, the
// selected point's fields, and the thesis's safe manipulators (opacity modulator, HU shift).
#include <optional>
#include <vector>

#include <imgui.h>

#include "core/transfer_function.h"
#include "core/volume.h"

namespace angio {

struct TfEditorView {
  double huMin = -1024, huMax = 3071;  // the visible HU range
  int selected = -1;                   // index of the selected point
  int dragging = -1;                   // index of the point being dragged
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
