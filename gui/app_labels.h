#pragma once
// The Labels section's runtime state: the work in the background (automatic removal, a grown
// region, a label file read) that ends in a label change, the undo and redo stacks of changes,
// the voxel counts per label and whether the labels differ from their file. How labels render
// is the document's (its main TF's label list). Drawn by gui/panel_labels.cpp, run by
// gui/app_labels.cpp.
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "core/slice_tiles.h"
#include "gui/background_job.h"
#include "gui/label_change.h"
#include "gui/panel_labels.h"

namespace angio {

// A label job's change, with the slice tiles of the changed volume when the job built them
// ahead (see tilesBuiltAhead in gui/app_labels.cpp), so that the renderer need not after it.
struct LabelJobResult {
  LabelChange change;
  std::shared_ptr<SliceTiles> tiles;
};

// What the label job does: a new change (removal, growing, a file), or undoes or redoes one.
enum class LabelStep { change, undo, redo };

struct LabelsPanel {
  LabelsPanelUi ui;
  BackgroundJob<LabelJobResult> job;  // its change is applied as one undo step (or undone, redone)
  std::string jobWhat;                // e.g. "removing bone and table"
  LabelStep jobStep = LabelStep::change;
  std::string fileRead;  // the label file the job reads ("" = another job)
  std::vector<LabelChange> undo, redo;
  LabelCounts voxels{};
  std::future<LabelCounts> counting;  // after a dataset change
  bool counted = false;
  bool dirty = false;            // changed since loaded or saved
  bool tilesBuiltAhead = false;  // the last change applied came with its slice tiles
  std::string pendingFile;       // the start's label file, read once the dataset is there
  std::string error;
};

}  // namespace angio
