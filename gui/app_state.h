#pragma once
// The workstation's long-lived state: one plain struct, drawn from every frame and printable as
// JSON (it becomes the session file). Runtime things (textures, the worker) live in App.
#include <map>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "render/progressive_renderer.h"
#include "core/render_params.h"
#include "core/transfer_function.h"
#include "io/session_file.h"

namespace angio {

// Rotation axis and angle (theta of the rendering model, kept in [0, 360)), zoom (1 = the whole
// volume fits the viewport), pan (screen pixels), drag speed, auto-spin: as a session keeps them.
using ViewState = SessionView;

// What a session keeps (dataset, view, TF with its MIP window, tfPreset, mode, shading, levels,
// cpr (the CPR view's and the DVR+CPR hybrid's settings), vesselGlyph (the VesselGlyph panel's
// settings and TFs, its centerline file), panelsOpen, recentFiles:
// io/session_file.h), and what only this run needs.
struct AppState : Session {
  std::string centerlinesFile;  // centerlines to load at start (`gui --centerlines`), if any
};

// theta wrapped into [0, 360).
double wrapDegrees(double degrees);

// The render parameters the state asks for (sampling left at its default: each level sets it).
RenderParams renderParamsOf(const AppState& state);

// The session file's JSON (io/session_file.h) of the state.
nlohmann::json toJson(const AppState& state);

// A session's contents into the state: everything but the dataset (the caller loads it) and the
// recent files (the app's own list).
void applySessionState(AppState& state, const Session& session);

// "phantom IxJxK" names the generated phantom rather than a file.
bool isPhantomName(const std::string& dataset);
// A dataset on disk as an absolute path (sessions and sidecars work from any folder), else as is.
std::string absoluteDataset(const std::string& dataset);

}  // namespace angio
