#pragma once
// The Export section: one image of the current view at a chosen image sampling distance, and a
// rotation series (render/series_export.h), each with its running job's progress and Cancel.
// The settings are the section's own; what it returns are requests.
#include <string>

#include "gui/panel_widgets.h"
#include "render/series_export.h"

namespace angio {

// The export section's rotation-series settings.
struct SeriesPanel {
  std::string folder = "angioray-series";
  SeriesSpec spec;
  std::string movieNote;         // of the last series
  std::string confirmingFolder;  // asked whether to overwrite its views ("" = not asking)
};

struct ExportPanelUi {
  std::string path = "angioray-export.png";
  double isd = 0.5;            // voxel units
  std::string confirmingPath;  // asked whether to overwrite it ("" = not asking)
};

// Whether an export to `path` would replace a file the user has: the image or its sidecar.
bool exportWouldOverwrite(const std::string& path);
// Whether a series of `prefix` in `folder` would replace files: a view ("prefix-NNN.*") or its
// movie ("prefix.mp4", "prefix.avi").
bool seriesWouldOverwrite(const std::string& folder, const std::string& prefix);

// A background job as the section shows it.
struct JobInfo {
  bool running = false;
  double progress = 0;  // [0, 1]
  double seconds = 0;   // since it started
  bool cancelRequested = false;
};

struct ExportRequests {
  bool start = false, cancel = false;
  bool browse = false;  // "...": the file browser fills the file (folder) field
};

ExportRequests drawImageExport(ExportPanelUi& ui, const JobInfo& job, WidgetRects& rects);
// The settings of `series` (folder, angles, format, movie) and its last movie note.
ExportRequests drawSeriesExport(SeriesPanel& series, const JobInfo& job, WidgetRects& rects);

}  // namespace angio
