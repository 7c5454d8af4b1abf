#pragma once
// Session files: what the workstation needs to come back to where the user left it (dataset,
// rotation axis and angle, zoom/pan, the full transfer function with its MIP window, shading,
// the quality levels' sampling, the CPR view and DVR+CPR hybrid settings, the VesselGlyph panel
// (centerline file, region shapes, focus and context TFs in full), which side-panel sections are
// open, recently opened files), as JSON. Written atomically; every problem reading one is an
// InputError, one line naming the file and the key.
// The window app writes the last session to lastSessionPath() when it quits.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/progressive_renderer.h"
#include "core/render_params.h"
#include "core/transfer_function.h"
#include "vessel/cpr_layout.h"
#include "vessel/vessel_glyph.h"

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

  friend bool operator==(const SessionView&, const SessionView&) = default;
};

// How the CPR section colours a CPR: grey through the CTA-lumen or calcium window
// (vessel/cpr_display.h), or through the VesselGlyph focus TF.
enum class CprColouring { ctaLumen = 0, calcium = 1, focusTf = 2 };

// The CPR section: the view beside the image and the DVR+CPR hybrid in the
// image share the path and the colouring. (The VesselGlyph settings the hybrid builds on are
// SessionVesselGlyph's.)
struct SessionCpr {
  bool shown = false;  // the CPR view beside the image
  CprMode mode = CprMode::straightened;
  int path = -1;       // centerline path index, -1 = all paths
  CprColouring colouring = CprColouring::ctaLumen;
  bool hybrid = false;       // the DVR+CPR hybrid (needs VesselGlyph on)
  double transitionMm = 0;   // the hybrid's transition band, 0 = hard edge

  friend bool operator==(const SessionCpr&, const SessionCpr&) = default;
};

// The VesselGlyph panel (gui/app_vessel.h): the centerline file and what the user
// set. JSON "vessel_glyph": {"centerlines", "centerlines_absolute", "enabled", "overlay", the
// settings in io/vessel_glyph_json.h's form, "outside": "clip" | "main-tf", "focus_tf",
// "context_tf" (TF JSON or null), "focus_preset", "context_preset"}.
struct SessionVesselGlyph {
  std::string centerlines;          // the centerline file as given ("" = none)
  std::string centerlinesAbsolute;  // the same, absolute when it was loaded (tried first)
  bool enabled = false;             // VesselGlyph rendering on
  bool overlay = true;              // the projected centerlines over the image
  VesselGlyphSettings settings;
  bool outsideRendered = false;     // the outside: rendered with the main TF, else clipped
  TransferFunction focusTf, contextTf;  // no points: the presets below, loaded on first use
  std::string focusPreset = "cta-vessels", contextPreset = "soft-tissue-context";  // "" = edited

  friend bool operator==(const SessionVesselGlyph&, const SessionVesselGlyph&) = default;
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
  SessionVesselGlyph vesselGlyph;
  std::map<std::string, bool> panelsOpen;  // side-panel section title -> open
  std::vector<std::string> recentFiles;    // newest first, at most kMaxRecentFiles

  friend bool operator==(const Session&, const Session&) = default;
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
