#pragma once
// The Data section: "Open..." (the file browser), the recent files, the background load's
// progress with Cancel, a failed load's error with Dismiss, and the shown dataset's dims,
// spacing, orientation and HU range. It edits no document: what it returns are requests.
#include <optional>
#include <string>

#include "core/volume.h"
#include "io/study_info.h"
#include "gui/panel_widgets.h"
#include "gui/workstation.h"

namespace angio {

// What the section shows of the app's dataset and its load.
struct DataPanelInfo {
  const Volume* volume = nullptr;  // the shown dataset's
  std::string name, description;
  StudyInfo study;
  std::optional<DensityRange> densities;  // none: still counting
  bool huCalibrated = true;               // with densities: they look like calibrated HU
  bool loading = false;
  double loadProgress = 0, loadSeconds = 0;  // while loading
  bool cancelRequested = false;
  std::string loadPath;   // being loaded, or the last one
  std::string loadError;  // the last load's ("" = none)
};

struct DataPanelRequests {
  bool browse = false;              // "Open...": show the file browser
  std::optional<std::string> open;  // a recent file chosen
  bool cancelLoad = false;
  bool dismissError = false;
};

DataPanelRequests drawDataPanel(const Document& document, const DataPanelInfo& info, WidgetRects& rects);

}  // namespace angio
