// The Vessels section in App: clicks on the image become tracer requests (gui/vessel_trace_job.h)
// run one at a time in the background, their outcomes change the document's path list as one
// undo step each; the whole volume's lumen field is built once per tracer after the first click
// found the contrast range (the tracer needs it for the field), so later traces take well under a
// second; save and load go through centerline files; a new dataset drops the paths.
#include <exception>
#include <filesystem>

#include <imgui.h>

#include "core/view_geometry.h"
#include "gui/app.h"
#include "gui/app_export.h"
#include "gui/vessel_files.h"

namespace angio {

namespace fs = std::filesystem;

namespace {

bool contains(ImVec2 min, ImVec2 max, ImVec2 p) {
  return p.x >= min.x && p.y >= min.y && p.x < max.x && p.y < max.y;
}

TraceSettings traceSettings(const VesselsPanelUi& ui) {
  TraceSettings settings;
  if (ui.fixedTissue) settings.tissueHu = ui.tissueHu;
  if (ui.fixedCalcium) settings.calciumHu = ui.calciumHu;
  return settings;
}

}  // namespace

void App::drawVesselsSection() {
  const ImVec2 top = ImGui::GetCursorScreenPos();
  // Closed until opened (as Labels): the sections below it stay in view on a small screen.
  if (!sectionHeader("Vessels", false)) {
    vessels_.focused = false;  // keys go to the TF editor again
    return;
  }
  VesselsPanel& v = vessels_;
  VesselsPanelInfo info;
  info.hasVolume = data_.volume.voxelCount() > 0;
  info.busy = v.job.running();
  info.busyWhat = v.jobWhat;
  info.progress = v.jobWhat == "trace downstream" ? v.job.progress() : -1;
  info.seconds = v.job.seconds();
  info.queued = int(v.queued.size());
  info.contrast = v.contrast;
  info.canUndo = !v.undo.empty();
  info.canRedo = !v.redo.empty();
  if (info.canUndo) info.undoWhat = v.undo.back().what;
  if (info.canRedo) info.redoWhat = v.redo.back().what;
  info.file = doc().vessels.file;
  info.unsaved = doc().vessels.unsaved;
  info.problem = v.problem;
  info.error = v.error;
  const VesselsPanelResult result = drawVesselsPanel(doc().vessels, v.ui, info, widgetRects_);
  const ImVec2 bottom = ImGui::GetCursorScreenPos();
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    v.focused = contains(ImVec2(top.x, top.y), ImVec2(top.x + kPanelWidth, bottom.y), mouse) ||
                (v.ui.traceTool && contains(viewport_.min, viewport_.max, mouse));
  }
  if (result.edit) changeVessels(result.edit->paths, result.what);
  if (result.removePoint)
    requestTrace({TraceAction::removePoint, v.ui.selectedPath, v.ui.selectedPoint, glm::dvec3(0.0)});
  if (result.settingsChanged) resetTracer();
  if (result.cancel) {
    v.queued.clear();
    v.job.cancel();
  }
  if (result.undo) undoVessels();
  if (result.redo) redoVessels();
  if (result.save) saveVessels(v.ui.path);
  if (result.load) loadVesselCenterlines({v.ui.path, "", CenterlineLoad::From::panel});
  if (result.browseSave) browseFor(BrowserPurpose::saveCenterlines, v.ui.path);
  if (result.browseLoad) browseFor(BrowserPurpose::loadCenterlines, v.ui.path);
}

// A click with the tool on: the visible point under it, for the tracer (in the background).
void App::traceOnClick() {
  VesselsPanel& v = vessels_;
  if (!v.ui.traceTool) return;
  const std::optional<glm::dvec2> imagePoint = clickedImagePoint();
  if (!imagePoint) return;
  const std::optional<PickedPoint> picked = pickVisible(*imagePoint);
  if (!picked) {
    v.problem = "nothing visible under the cursor";
    message_ = v.problem;
    return;
  }
  TraceRequest request{TraceAction::addPoint, -1, -1, picked->positionMm};
  if (v.ui.click == TraceClick::movePoint) {
    request.action = TraceAction::movePoint;
    request.path = v.ui.selectedPath;
    request.point = v.ui.selectedPoint;
    v.ui.click = TraceClick::addPoint;
  } else if (v.ui.click == TraceClick::downstream) {
    request.action = TraceAction::downstream;
    v.ui.click = TraceClick::addPoint;
  }
  requestTrace(request);
}

// A click on the CPR view with the tool on: the centerline point the clicked pixel's line passes
// through (the CPR's own geometry), as a click on the image would give it.
void App::traceOnCprClick(const CprPick& pick) {
  if (!vessels_.ui.traceTool) return;
  const Centerlines* centerlines = framedCenterlines();
  if (!centerlines || pick.path < 0 || pick.path >= int(centerlines->paths.size())) return;
  const CenterlinePath& path = centerlines->paths[pick.path];
  const std::vector<double> arcs = arcLengthsMm(path);
  if (arcs.empty()) return;
  const std::size_t n =
      std::size_t(std::lower_bound(arcs.begin(), arcs.end(), pick.arcMm) - arcs.begin());
  requestTrace({TraceAction::addPoint, -1, -1, path.points[std::min(n, arcs.size() - 1)].positionMm});
}

void App::requestTrace(const TraceRequest& request) {
  vessels_.queued.push_back(request);
  if (!vessels_.job.running()) startNextTrace();
}

// The next request, with the path it changes as the document has it now: a click adds to the
// selected path (one traced here), else starts a new one.
void App::startNextTrace() {
  VesselsPanel& v = vessels_;
  if (v.job.running() || v.queued.empty()) return;
  TraceRequest request = v.queued.front();
  v.queued.pop_front();
  const std::vector<VesselPath>& paths = doc().vessels.paths;
  if (request.action == TraceAction::addPoint) {
    const int selected = v.ui.selectedPath;
    const bool traceable =
        selected >= 0 && selected < int(paths.size()) && !paths[selected].controlPointsMm.empty();
    request.path = traceable ? selected : -1;
  }
  VesselPath path{newPathName(paths), {}, {}};
  if (request.path >= 0 && request.path < int(paths.size())) path = paths[request.path];
  if (!v.tracer) v.tracer = std::make_unique<VesselTracer>(data_.volume, traceSettings(v.ui));
  v.jobWhat = request.action == TraceAction::prepare      ? "lumen field"
              : request.action == TraceAction::downstream ? "trace downstream"
                                                          : "tracing " + path.name;
  v.job.start([this, tracer = v.tracer.get(), request, path](JobControl& control) {
    return runTrace(*tracer, data_.volume, request, path, control);
  });
}

void App::pollVesselJobs() {
  VesselsPanel& v = vessels_;
  if (!v.job.ready()) return startNextTrace();
  const double seconds = v.job.seconds();
  try {
    const TraceOutcome outcome = v.job.take();
    v.contrast = outcome.contrast;
    if (outcome.request.action == TraceAction::prepare) {
      char took[64];
      std::snprintf(took, sizeof took, " (%.1f s)", seconds);
      message_ = outcome.cancelled ? "lumen field cancelled: each trace prepares its own box"
                                   : "lumen field ready" + std::string(took);
    } else if (outcome.cancelled) {
      message_ = outcome.what + " cancelled";
    } else if (outcome.paths.empty()) {
      v.problem = outcome.problem;
      message_ = outcome.what + ": " + outcome.problem;
    } else {
      v.problem.clear();
      const bool added = outcome.request.path < 0 || outcome.request.action == TraceAction::downstream;
      changeVessels(withOutcome(doc().vessels.paths, outcome), outcome.what);
      if (added) v.ui.selectedPath = int(doc().vessels.paths.size() - outcome.paths.size());
      message_ = outcome.what;
    }
  } catch (const std::exception& error) {
    v.problem = error.what();
    message_ = error.what();
  }
  if (!v.fieldAsked && v.contrast) {
    v.fieldAsked = true;
    v.queued.push_front({TraceAction::prepare, -1, -1, glm::dvec3(0.0)});
  }
  startNextTrace();
}

void App::changeVessels(std::vector<VesselPath> paths, const std::string& what) {
  vessels_.undo.push_back({doc().vessels.paths, what});
  vessels_.redo.clear();
  commit(VesselPathsEdit{std::move(paths)});
}

// Undo and redo: the top of one stack becomes the list, the list goes onto the other.
void App::stepVessels(std::vector<VesselsStep>& from, std::vector<VesselsStep>& to, const char* done) {
  if (from.empty()) return;
  VesselsStep step = std::move(from.back());
  from.pop_back();
  to.push_back({doc().vessels.paths, step.what});
  commit(VesselPathsEdit{std::move(step.paths)});
  message_ = done + (" " + step.what);
}

void App::undoVessels() { stepVessels(vessels_.undo, vessels_.redo, "undid"); }
void App::redoVessels() { stepVessels(vessels_.redo, vessels_.undo, "redid"); }

void App::resetTracer() {
  vessels_.job.stop();
  vessels_.queued.clear();
  vessels_.tracer.reset();
  vessels_.fieldAsked = false;
  vessels_.contrast.reset();
}

// Called once the new dataset is the document's (DatasetOpened dropped the old one's paths); a
// session's own paths come with its SessionEdit after that.
void App::resetVessels() {
  resetTracer();
  vessels_.undo.clear();
  vessels_.redo.clear();
  vessels_.problem.clear();
  vessels_.ui.selectedPath = vessels_.ui.selectedPoint = -1;
}

void App::saveVessels(const std::string& file) {
  try {
    const Centerlines readBack = writeAndReadBack(centerlinesOf(doc().vessels), file);
    const std::string absolute = fs::absolute(file).lexically_normal().string();
    commit(VesselFileEdit{withReadBack(doc().vessels.paths, readBack), absolute});
    commit(CenterlineFileEdit{file, absolute});
    vessels_.error.clear();
    message_ = "saved " + std::to_string(readBack.paths.size()) + " vessel paths to " + file;
  } catch (const std::exception& error) {
    vessels_.error = error.what();
  }
}

void App::chooseVesselFile(const fs::path& file) {
  vessels_.ui.path = file.string();
  if (browser_.purpose == BrowserPurpose::saveCenterlines) saveVessels(vessels_.ui.path);
  else loadVesselCenterlines({vessels_.ui.path, "", CenterlineLoad::From::panel});
}

// The paths an export renders but no file holds as they are.
std::optional<Centerlines> App::unsavedCenterlines() const {
  const VesselsState& vessels = doc().vessels;
  if (!scene_ || !scene_->hasRegions() || (!vessels.unsaved && !vessels.file.empty()))
    return std::nullopt;
  return centerlinesOf(vessels);
}

// The selected path's control points over the image (the paths themselves are the centerline
// overlay's), the selected point larger.
void App::drawTraceOverlay() {
  const VesselsPanelUi& ui = vessels_.ui;
  const std::vector<VesselPath>& paths = doc().vessels.paths;
  if (!shown_ || !viewport_.hasImage || ui.selectedPath < 0 || ui.selectedPath >= int(paths.size()))
    return;
  const ViewGeometry& view = shownView_;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(viewport_.min, viewport_.max, true);
  const std::vector<glm::dvec3>& points = paths[ui.selectedPath].controlPointsMm;
  for (int n = 0; n < int(points.size()); ++n) {
    const ImVec2 at = dvrScreenOf(view, volumeFrameMm(data_.volume, points[n]));
    const bool selected = n == ui.selectedPoint;
    draw->AddCircleFilled(at, selected ? 6.f : 4.f, IM_COL32(255, 210, 40, 230));
    draw->AddCircle(at, selected ? 7.f : 5.f, IM_COL32(0, 0, 0, 200));
  }
  draw->PopClipRect();
}

nlohmann::json App::vesselsReport() const {
  nlohmann::json paths = nlohmann::json::array();
  for (const VesselPath& path : doc().vessels.paths) {
    nlohmann::json controls = nlohmann::json::array();
    for (const glm::dvec3& p : path.controlPointsMm) controls.push_back({p.x, p.y, p.z});
    paths.push_back({{"name", path.name},
                     {"points", path.centerline.points.size()},
                     {"length_mm", pathLengthMm(path.centerline)},
                     {"control_points_mm", controls}});
  }
  const VesselsPanel& v = vessels_;
  nlohmann::json contrast = nullptr;
  if (v.contrast) contrast = {v.contrast->lowHu, v.contrast->highHu};
  return {{"paths", paths},
          {"file", doc().vessels.file},
          {"unsaved", doc().vessels.unsaved},
          {"trace_tool", v.ui.traceTool},
          {"selected_path", v.ui.selectedPath},
          {"busy", v.job.running()},
          {"queued", v.queued.size()},
          {"contrast_hu", contrast},
          {"undo", v.undo.size()},
          {"redo", v.redo.size()},
          {"problem", v.problem},
          {"error", v.error},
          {"focused", v.focused}};
}

}  // namespace angio
