#pragma once
// Session files: what the workstation needs to come back to where the user left it (dataset,
// rotation axis and angle, zoom/pan, the full transfer function with its MIP window, shading,
// the quality levels' sampling, the CPR view and DVR+CPR hybrid settings, which side-panel
// sections are open, recently opened files), as
// JSON. Written atomically; every problem reading one is an InputError, one line naming the file.
// The window app writes the last session to lastSessionPath() when it quits.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/progressive_renderer.h"
#include "core/render_params.h"
#include "core/transfer_function.h"
#include "vessel/cpr_layout.h"

namespace angio {

constexpr std::size_t kMaxRecentFiles = 10;

struct SessionView {
  Axis axis = Axis::k;
  double angleDeg = 0;
  double zoom = 1;
  glm::dvec2 panPx{0.0};  // screen pixels
  double degreesPerPixel = 0.5;
  bool autoSpin = false;
  double spinDegreesPerSecond = 30;
};

// How the CPR section colours a CPR: grey through the CTA-lumen or calcium window
// (vessel/cpr_display.h), or through the VesselGlyph focus TF.
enum class CprColouring { ctaLumen = 0, calcium = 1, focusTf = 2 };

// The CPR section (issue 6 items 4-6): the view beside the image and the DVR+CPR hybrid in the
// image share the path and the colouring. (The VesselGlyph settings the hybrid builds on -
// centerlines, shapes, region TFs - are not kept in sessions.)
struct SessionCpr {
  bool shown = false;  // the CPR view beside the image
  CprMode mode = CprMode::straightened;
  int path = -1;       // centerline path index, -1 = all paths
  CprColouring colouring = CprColouring::ctaLumen;
  bool hybrid = false;       // the DVR+CPR hybrid (needs VesselGlyph on)
  double transitionMm = 0;   // the hybrid's transition band, 0 = hard edge
};

struct Session {
  std::string dataset;  // file or folder; "phantom IxJxK" for the generated phantom
  SessionView view;
  TransferFunction tf;   // includes the MIP window/level
  std::string tfPreset;  // empty if edited or loaded from a file
  Compositing mode = Compositing::dvr;
  Shading shading;
  LevelSamplings levels = defaultLevelSamplings();
  SessionCpr cpr;
  std::map<std::string, bool> panelsOpen;  // side-panel section title -> open
  std::vector<std::string> recentFiles;    // newest first, at most kMaxRecentFiles
};

std::string toJson(const Session& session);
Session parseSession(const std::string& json, const std::filesystem::path& source);
Session loadSession(const std::filesystem::path& path);
void saveSession(const Session& session, const std::filesystem::path& path);  // atomic

// $XDG_CONFIG_HOME/angioray, else $HOME/.config/angioray (created by saveSession as needed).
std::filesystem::path configDirectory();
// configDirectory() / "last-session.json".
std::filesystem::path lastSessionPath();

// Puts `path` first in `recent` (removing an older entry of it), keeping kMaxRecentFiles.
void addRecentFile(std::vector<std::string>& recent, const std::string& path);

}  // namespace angio
