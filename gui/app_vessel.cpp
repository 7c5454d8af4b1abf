// VesselGlyph in App (thesis ch. 5): centerlines loaded in the background, shown over the image,
// the panel (gui/panel_vessel_glyph.h) drawn and its edits applied; every change makes a new
// prepared scene (gui/app_recipe.cpp), which the progressive renderer takes as a new request
// (fast, medium, high as for any other change).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>

#include <imgui.h>

#include "core/view_geometry.h"
#include "gui/app.h"
#include "gui/vessel_trace_job.h"
#include "io/centerline_file.h"

namespace angio {

namespace fs = std::filesystem;

ImVec2 App::dvrScreenOf(const ViewGeometry& shownView, const glm::dvec3& pointMm) const {
  const glm::dvec2 pixel = imagePointOf(shownView, pointMm);
  const ImVec2 origin = viewport_.imageMin;
  return {origin.x + float(pixel.x / std::max(shownView.width, 1)) * (viewport_.imageMax.x - origin.x),
          origin.y + float(pixel.y / std::max(shownView.height, 1)) * (viewport_.imageMax.y - origin.y)};
}

// Reads the file off the UI thread; pollCenterlineLoad takes the result.
void App::loadVesselCenterlines(const CenterlineLoad& request) {
  VesselGlyphPanel& vg = vessel_;
  vg.loading = request;
  vg.error.clear();
  message_ = "loading centerlines " + request.given;
  vg.load.start([request](JobControl&) {
    // A session's absolute path first (it works from any folder), else the file as given; when
    // neither exists, the error names the absolute one.
    std::error_code error;
    const bool absoluteThere = !request.absolute.empty() && fs::exists(request.absolute, error);
    LoadedCenterlines loaded;
    loaded.file = absoluteThere || (!request.absolute.empty() && !fs::exists(request.given, error))
                      ? request.absolute
                      : request.given;
    CenterlineLoadOptions options;
    options.warn = [&loaded](const std::string& warning) { loaded.warnings += warning + "\n"; };
    loaded.physical = loadCenterlines(loaded.file, options);
    return loaded;
  });
}

// The document's centerline file, loaded in the background. Paths a session keeps inline that no
// file holds (traced, unsaved) are the session's own; saved ones are read again from their file,
// so a file changed since is what opens, and a missing one says so.
void App::loadSessionCenterlines() {
  const VesselGlyphState& set = doc().vesselGlyph;
  vessel_.load.stop();
  dropCenterlines();
  if (doc().vessels.unsaved && !doc().vessels.paths.empty()) return;
  if (set.centerlines.empty() && set.centerlinesAbsolute.empty()) return;
  vessel_.ui.path = set.centerlines.empty() ? set.centerlinesAbsolute : set.centerlines;
  loadVesselCenterlines({vessel_.ui.path, set.centerlinesAbsolute, CenterlineLoad::From::session});
}

void App::dropCenterlines() {
  vessel_.warnings.clear();
  vessel_.error.clear();
}

// The document's vessel paths as the centerlines everything else draws from, mapped again when
// they change (their revision) or the dataset does.
void App::syncVesselCenterlines() {
  VesselGlyphPanel& vg = vessel_;
  vg.file = doc().vessels.file;
  if (vg.revision == doc().vessels.revision && vg.revisionKnown) return;
  vg.revision = doc().vessels.revision;
  vg.revisionKnown = true;
  Centerlines centerlines = centerlinesOf(doc().vessels);
  if (centerlines.paths.empty()) vg.physical.reset();
  else vg.physical = std::move(centerlines);
  vg.inVolume.reset();
}

// Once loaded and no dataset load is running (the points are checked against the shown dataset):
// the file's paths replace the list (one undo step when the user asked for it).
void App::pollCenterlineLoad() {
  VesselGlyphPanel& vg = vessel_;
  if (!vg.load.ready() || load_.running()) return;
  try {
    LoadedCenterlines loaded = vg.load.take();
    CenterlineLoadOptions options;
    options.warn = [&loaded](const std::string& warning) { loaded.warnings += warning + "\n"; };
    checkCenterlinesInside(loaded.physical, data_.volume, options);
    char summary[160];
    std::snprintf(summary, sizeof summary, "loaded %zu centerline paths (%zu points) from ",
                  loaded.physical.paths.size(), centerlinePointCount(loaded.physical));
    message_ = summary + loaded.file;
    vg.warnings = std::move(loaded.warnings);
    vg.error.clear();
    std::error_code error;
    const fs::path absolute = fs::absolute(loaded.file, error);
    const std::string file = error ? loaded.file : absolute.lexically_normal().string();
    if (vg.loading.from == CenterlineLoad::From::panel) {
      vessels_.undo.push_back({doc().vessels.paths, "load " + loaded.file});
      CprState cpr = doc().cpr;
      cpr.cursor.reset();  // it was on the paths this file replaces (a session's stays)
      commit(CprEdit{cpr});
    }
    commit(VesselFileEdit{importedPaths(loaded.physical), file});
    commit(CenterlineFileEdit{vg.loading.given, file});
  } catch (const std::exception& error) {
    vg.error = error.what();
    message_ = error.what();
    // A session's file that is gone or broken: the rest of the session stands, VesselGlyph is off.
    if (vg.loading.from == CenterlineLoad::From::session) {
      commit(VesselFileEdit{});
      VesselGlyphState off = doc().vesselGlyph;
      off.enabled = false;
      commit(VesselGlyphEdit{off});
    }
  }
}

// The centerlines in the shown dataset's volume frame (mapped again after a dataset change).
const Centerlines* App::framedCenterlines() {
  VesselGlyphPanel& vg = vessel_;
  if (!vg.physical) return nullptr;
  const glm::ivec3 dims = data_.volume.dims;
  const std::string key = data_.name + " " + std::to_string(dims.x) + "x" + std::to_string(dims.y) +
                          "x" + std::to_string(dims.z);
  if (!vg.inVolume || vg.framedFor != key) {
    vg.inVolume = toVolumeFrame(*vg.physical, data_.volume);
    vg.framedFor = key;
  }
  return &*vg.inVolume;
}

void App::loadMissingRegionTfs() {
  const VesselGlyphState& set = doc().vesselGlyph;
  try {
    if (!set.focusFollowsMain && set.focusTf.points.empty())
      commit(TfChange{TfTarget::focus, loadPresetOrFile(set.focusPreset), set.focusPreset});
    if (!set.contextFollowsMain && set.contextTf.points.empty())
      commit(TfChange{TfTarget::context, loadPresetOrFile(set.contextPreset), set.contextPreset});
  } catch (const std::exception& error) {
    message_ = error.what();
  }
}

void App::drawVesselSection() {
  if (!sectionHeader("VesselGlyph")) return;
  loadMissingRegionTfs();
  VesselGlyphPanel& vg = vessel_;
  VesselGlyphPanelInfo info;
  info.loading = vg.load.running();
  info.loadingFile = vg.loading.given;
  info.physical = vg.physical ? &*vg.physical : nullptr;
  info.file = vg.file.empty() ? "traced in the Vessels section" : vg.file;
  info.warnings = vg.warnings;
  info.error = vg.error;
  info.problem = vg.problem;
  info.presets = &presets_;
  const VesselGlyphPanelResult result =
      drawVesselGlyphPanel(doc().vesselGlyph, vg.ui, info, widgetRects_);
  if (!result.message.empty()) message_ = result.message;
  if (result.edit) commit(*result.edit);
  if (result.loadCenterlines) loadVesselCenterlines({vg.ui.path, "", CenterlineLoad::From::panel});
  if (result.browseCenterlines) browseFor(BrowserPurpose::glyphCenterlines, vg.ui.path);
}

constexpr float kOverlayStepPx = 1.5f;

// A path's points from `first` on, on screen, a pixel or more apart: a traced run-off tree has
// paths of thousands of points at 0.5 mm.
template <class ToScreen>
void overlayPoints(const ToScreen& toScreen, const CenterlinePath& path, std::size_t first,
                   std::vector<ImVec2>& screen) {
  screen.clear();
  for (std::size_t n = first; n < path.points.size(); ++n) {
    const ImVec2 at = toScreen(path.points[n].positionMm);
    if (!screen.empty() && n + 1 < path.points.size()) {
      const float dx = at.x - screen.back().x, dy = at.y - screen.back().y;
      if (dx * dx + dy * dy < kOverlayStepPx * kOverlayStepPx) continue;
    }
    screen.push_back(at);
  }
}

// The centerlines projected with the shown frame's view, over the image (follows zoom and pan).
void App::drawCenterlineOverlay() {
  if (!doc().vesselGlyph.overlay || !vessel_.physical || !shown_ || !viewport_.hasImage) return;
  const Centerlines* centerlines = nullptr;
  try {
    centerlines = framedCenterlines();
  } catch (const std::exception& error) {
    vessel_.problem = error.what();
    return;
  }
  const ViewGeometry& view = shownView_;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(viewport_.min, viewport_.max, true);
  std::vector<ImVec2> screen;
  const auto& paths = centerlines->paths;
  for (std::size_t p = 0; p < paths.size(); ++p) {
    // A trunk repeated in later paths (vmtk's layout) is drawn once, with the first.
    std::size_t first = 0;
    for (std::size_t earlier = 0; earlier < p; ++earlier)
      first = std::max(first, sharedPrefixLength(paths[p], paths[earlier]));
    overlayPoints([&](glm::dvec3 mm) { return dvrScreenOf(view, mm); }, paths[p],
                  first == 0 ? 0 : first - 1, screen);
    // A 16-bit ImGui draw list holds 65536 vertices; a thick polyline takes 4 per point.
    if (screen.size() < 2 || draw->_VtxCurrentIdx + 4 * screen.size() + 64 > 65535) continue;
    // Opaque: a trunk drawn once must show as strongly as when every path through it drew it.
    draw->AddPolyline(screen.data(), int(screen.size()), IM_COL32(40, 230, 255, 255), ImDrawFlags_None,
                      1.5f);
  }
  draw->PopClipRect();
}

}  // namespace angio
