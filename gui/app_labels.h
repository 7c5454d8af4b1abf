#pragma once
// The Labels section's runtime state: the work in the background (automatic removal, a grown
// region, a label file read) that ends in a label change, the undo and redo stacks of changes,
// the voxel counts per label and whether the labels differ from their file. How labels render
// is the document's (its main TF's label list). Drawn by gui/panel_labels.cpp, run by
// gui/app_labels.cpp.
#include <future>
#include <string>
#include <vector>

#include "gui/background_job.h"
#include "gui/label_change.h"
#include "gui/panel_labels.h"

namespace angio {

struct LabelsPanel {
  LabelsPanelUi ui;
  BackgroundJob<LabelChange> job;  // its result is applied as one undo step
  std::string jobWhat;             // e.g. "removing bone and table"
  std::string fileRead;            // the label file the job reads ("" = another job)
  std::vector<LabelChange> undo, redo;
  LabelCounts voxels{};
  std::future<LabelCounts> counting;  // after a dataset change
  bool counted = false;
  bool dirty = false;       // changed since loaded or saved
  std::string pendingFile;  // the start's label file, read once the dataset is there
  std::string error;
};

}  // namespace angio
