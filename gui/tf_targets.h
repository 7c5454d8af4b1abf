#pragma once
// What the TF editor edits (the main TF, or VesselGlyph's focus or context TF) and an undo stack
// per target, so that switching keeps each one's history.
#include <array>

#include "gui/document.h"
#include "gui/tf_editor.h"

namespace angio {

class TfTargets {
 public:
  TfTarget editing() const { return editing_; }
  void edit(TfTarget target) { editing_ = target; }
  // The undo stack of the TF being edited.
  TfHistory& history() { return histories_[int(editing_)]; }
  const TfHistory& history() const { return histories_[int(editing_)]; }

 private:
  TfTarget editing_ = TfTarget::main;
  std::array<TfHistory, 3> histories_;
};

}  // namespace angio
