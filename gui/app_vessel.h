#pragma once
// The VesselGlyph panel's runtime state (thesis ch. 5): the loaded centerlines, mapped into the
// shown dataset's frame, and why VesselGlyph or the hybrid is not rendered. What the user set (centerline file, shapes, focus / context TFs) is the document's
// VesselGlyphState. Drawn by gui/panel_vessel_glyph.cpp, run by gui/app_vessel.cpp.
#include <cstdint>
#include <optional>
#include <string>

#include "core/view_geometry.h"
#include "gui/background_job.h"
#include "gui/document.h"
#include "gui/panel_vessel_glyph.h"
#include "vessel/centerline.h"
#include "vessel/vessel_glyph.h"

namespace angio {

// A centerline file being read off the UI thread: the panel's button, `gui --centerlines`, a
// session (which names the file as given and as an absolute path: the first that exists is read).
struct CenterlineLoad {
  std::string given;     // as the user or the session named it
  std::string absolute;  // the session's absolute path, "" = make it from `given`
  enum class From { panel, session } from = From::panel;  // a session's failure turns VesselGlyph off
};
struct LoadedCenterlines {
  Centerlines physical;
  std::string file;      // the file read
  std::string warnings;  // one per line
};

struct VesselGlyphPanel {
  VesselGlyphPanelUi ui;  // the "Load centerlines..." field

  // Loading (pollCenterlineLoad takes the result once the dataset is there to check it against).
  CenterlineLoad loading;
  BackgroundJob<LoadedCenterlines> load;

  // The document's vessel paths (VesselsState) as centerlines, physical (LPS mm), none when
  // there are none; remade when their revision changes.
  std::optional<Centerlines> physical;
  std::string file;  // where they came from ("" = traced)
  std::uint64_t revision = 0;
  bool revisionKnown = false;
  std::string warnings;  // the loader's, one per line
  std::string error;     // the last load's error, shown in the panel

  // Derived, rebuilt on change (UI thread).
  std::optional<Centerlines> inVolume;  // physical mapped into the shown dataset's volume frame
  std::string framedFor;                // the dataset inVolume was mapped for
  std::string problem;                  // why VG is not rendered although enabled
  std::string hybridProblem;            // why the hybrid is not rendered although on
};

}  // namespace angio
