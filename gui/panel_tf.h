#pragma once
// The Transfer function section: which TF the editor edits (main, or VesselGlyph's focus or
// context once there are centerlines), the preset combo, undo/redo, the editor
// (gui/tf_editor.h), a TF file's path with Load and Save. Presets and files are read here; what
// the app does with them (an undo step, the edit, the save) it is asked for.
#include <optional>
#include <string>
#include <vector>

#include "gui/panel_widgets.h"
#include "gui/tf_editor.h"
#include "gui/workstation.h"
#include "io/tf_file.h"

namespace angio {

struct TfPanelUi {
  TfEditorView editor;
  std::string path = "transfer-function.json";
};

// What the section shows of the app's TF editing.
struct TfPanelInfo {
  TfTarget editing = TfTarget::main;
  bool targetsShown = false;  // the main | focus | context choice
  bool canUndo = false, canRedo = false;
  const std::vector<float>* histogram = nullptr;  // log counts per density (empty: not yet)
  const std::vector<Preset>* presets = nullptr;
};

struct TfPanelRequests {
  std::optional<TfTarget> switchTo;
  // A preset or a file chosen: the edited TF becomes it (one undo step).
  std::optional<TfChange> replace;
  // The editor's: the edited TF, and the TF before a gesture that ended (one undo step).
  std::optional<TfChange> edit;
  std::optional<TransferFunction> committedBefore;
  bool undo = false, redo = false;
  bool save = false;    // the edited TF to ui.path
  bool browse = false;  // "...": the file browser fills ui.path
  std::string message;  // what was loaded, or why not
};

TfPanelRequests drawTfPanel(const Document& document, TfPanelUi& ui, const TfPanelInfo& info,
                            WidgetRects& rects);

}  // namespace angio
