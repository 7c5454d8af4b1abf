// TF editing in App: the Transfer function section (gui/panel_tf.h) and what it asks for, the
// editor's target (main, focus or context) with an undo stack each (gui/tf_targets.h).
#include <algorithm>
#include <cmath>
#include <exception>

#include "gui/app.h"
#include "gui/panel_tf.h"

namespace angio {

const std::string& App::editedPreset() const { return presetOf(doc(), tfTargets_.editing()); }

TransferFunction App::editedTf() const { return tfOf(doc(), tfTargets_.editing()); }

void App::applyTf(const TransferFunction& tf, const std::string& preset) {
  applyTfChange(TfChange{tfTargets_.editing(), tf, preset});
}

void App::applyTfChange(const TfChange& change) {
  tfTargets_.history().push(editedTf());
  commit(change);
  tfPanel_.editor.selected = tfPanel_.editor.dragging = -1;
}

// Shift+drag on the view, as Horos and Slicer adjust windows in their views: in DVR right/left
// moves the edited TF along HU (the safe HU shift, thesis 4.2.2), up/down scales its opacity;
// in MIP right/left widens/narrows the window, up/down raises/lowers the level.
void App::adjustByDrag(glm::vec2 px) {
  constexpr double kHuPerPx = 2, kOpacityPerPx = 0.01, kWindowPerPx = 4, kLevelPerPx = 2;
  if (doc().mode == Compositing::mip) {
    const TransferFunction& tf = doc().tf;
    commit(RenderingEdit{doc().mode, doc().shading, std::max(1.0, tf.mipWindow + px.x * kWindowPerPx),
                         tf.mipLevel - px.y * kLevelPerPx, levelsPreintegrated(doc()),
                         doc().levels[0].adaptive, doc().levels[0].adaptiveSampling});
    return;
  }
  TransferFunction tf = editedTf();
  if (!viewAdjusting_) tfTargets_.history().push(tf);  // the whole drag: one undo step
  viewAdjusting_ = true;
  TfModulators& m = tf.modulators;
  m.huShift = std::clamp(m.huShift + px.x * kHuPerPx, -500.0, 500.0);
  m.opacityScale = std::clamp(m.opacityScale * std::exp(-px.y * kOpacityPerPx), 0.0, 3.0);
  commit(TfChange{tfTargets_.editing(), tf, ""});
}

void App::undoTf() {
  if (tfPanel_.editor.gestureBefore) return;  // not in the middle of an edit
  if (auto previous = tfTargets_.history().undo(editedTf()))
    commit(TfChange{tfTargets_.editing(), *previous, ""});
}

void App::redoTf() {
  if (tfPanel_.editor.gestureBefore) return;
  if (auto next = tfTargets_.history().redo(editedTf()))
    commit(TfChange{tfTargets_.editing(), *next, ""});
}

void App::drawTfSection() {
  if (!sectionHeader("Transfer function")) return;
  TfPanelInfo info;
  info.editing = tfTargets_.editing();
  info.targetsShown = vessel_.physical || tfTargets_.editing() != TfTarget::main;
  info.canUndo = tfTargets_.history().canUndo();
  info.canRedo = tfTargets_.history().canRedo();
  info.histogram = &histogram_;
  info.presets = &presets_;
  TfPanelRequests requests = drawTfPanel(doc(), tfPanel_, info, widgetRects_);
  if (!requests.message.empty()) message_ = requests.message;
  if (requests.replace) applyTfChange(*requests.replace);
  if (requests.undo) undoTf();
  if (requests.redo) redoTf();
  if (requests.committedBefore) tfTargets_.history().push(*requests.committedBefore);
  if (requests.edit) commit(*requests.edit);
  if (requests.save) saveEditedTf();
  if (requests.browse) browseFor(BrowserPurpose::tfFile, tfPanel_.path);
  if (requests.switchTo)
    switchTfTarget(*requests.switchTo);  // last: the requests above are the old target's
}

void App::saveEditedTf() {
  try {
    saveTransferFunction(editedTf(), tfPanel_.path);
    message_ = "saved " + tfPanel_.path;
  } catch (const std::exception& error) {
    message_ = error.what();
  }
}

// Each target keeps its own undo stack; not in the middle of an edit gesture.
void App::switchTfTarget(TfTarget target) {
  if (tfPanel_.editor.gestureBefore) return;
  loadMissingRegionTfs();
  tfTargets_.edit(target);
  tfPanel_.editor.selected = tfPanel_.editor.dragging = -1;
}

}  // namespace angio
