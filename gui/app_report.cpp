// App::report(): the document and the runtime numbers as JSON, for --state-out, scripts' "state"
// steps and the tests (the layout of named widgets lets scripts click them).
#include <string>

#include "gui/app.h"
#include "gui/study_banner.h"
#include "io/sampling_json.h"
#include "vessel/vessel_glyph_spec.h"

namespace angio {

namespace {

// FNV-1a of the shown pixels: lets tests tell images apart without reading screenshots.
std::uint64_t checksum(const std::vector<std::uint8_t>& bytes) {
  std::uint64_t hash = 1469598103934665603ull;
  for (std::uint8_t byte : bytes) hash = (hash ^ byte) * 1099511628211ull;
  return hash;
}

nlohmann::json rectJson(ImVec2 min, ImVec2 max) { return {min.x, min.y, max.x, max.y}; }

nlohmann::json statsJson(const FrameTimes::Stats& stats) {
  return {{"frames", stats.frames}, {"mean_ms", stats.meanMs()}, {"max_ms", stats.maxMs}};
}

// A region TF as the report names it: what it follows, its preset, or its own name.
std::string regionTfName(const Document& document, TfTarget region) {
  if (followsMainTf(document, region)) return followingTfLabel(region);
  const std::string& preset = presetOf(document, region);
  return preset.empty() ? tfOf(document, region).name : preset;
}

}  // namespace

nlohmann::json App::report() const {
  nlohmann::json shown = nullptr;
  if (shown_) {
    const Sampling& s = shown_->params.sampling;
    shown = {{"request", shown_->request},
             {"level", toString(shown_->level)},
             {"width", shown_->image->width},
             {"height", shown_->image->height},
             {"angle_deg", shown_->params.angleDeg},
             {"axis", toString(shown_->params.axis)},
             {"render_ms", shown_->renderMs},
             {"samples", shown_->samples},
             {"checksum", std::to_string(checksum(shown_->display->levels.front().rgb))}};
    // isd, osd, filter, ert and the approximations, named as sidecars and sessions name them.
    shown.update(nlohmann::json(samplingJson(s)));
  }
  const ProgressiveStatus status = renderer_->status();
  nlohmann::json levels = nlohmann::json::object();
  for (int q = 0; q < kQualityLevels; ++q) {
    const LevelTiming& t = status.levels[q];
    if (t.done)
      levels[toString(Quality(q))] = {{"ms", t.ms}, {"samples_per_second", t.samplesPerSecond()}};
  }
  const OrientationLetters letters = orientationLetters(doc().view.axis, doc().view.angleDeg);
  nlohmann::json layout = {{"viewport", rectJson(viewport_.min, viewport_.max)},
                           {"tf_plot", rectJson(tfPanel_.editor.plotMin, tfPanel_.editor.plotMax)}};
  if (viewport_.hasImage) layout["viewport_image"] = rectJson(viewport_.imageMin, viewport_.imageMax);
  for (const auto& [name, rect] : widgetRects_) layout[name] = rectJson(rect.first, rect.second);
  return {
      {"state", nlohmann::json::parse(toJson(doc()))},
      {"runtime",
       {{"dataset",
         {{"name", data_.name},
          {"dims", {data_.volume.dims.x, data_.volume.dims.y, data_.volume.dims.z}}}},
        {"shown", shown},
        {"newest_request", lastRequestId_},
        {"busy", status.busy},
        {"levels", levels},
        {"last_interrupt_ms", status.lastInterruptMs},
        {"startup_to_first_image_ms", startupImageMs_},
        {"renderer_first_image_ms", rendererFirstImageMs_},
        {"input_to_first_image_ms",
         {{"last", lastFirstImageMs_},
          {"count", firstImage_.frames},
          {"mean", firstImage_.meanMs()},
          {"max", firstImage_.maxMs}}},
        {"latency", latency_.report()},
        {"texture_upload_ms", {{"last", lastUploadMs_}, {"max", maxUploadMs_}}},
        {"ui_frame_ms",
         {{"all", statsJson(frameTimes_.all)}, {"while_high", statsJson(frameTimes_.whileHigh)}}},
        {"orientation",
         {{"right", std::string(1, letters.right)},
          {"left", std::string(1, letters.left)},
          {"top", std::string(1, letters.top)},
          {"bottom", std::string(1, letters.bottom)}}},
        {"tf_undo_available", tfTargets_.history().canUndo()},
        {"tf_editor_hu", {tfPanel_.editor.huMin, tfPanel_.editor.huMax}},
        {"message", message_},
        {"data", dataReport()},
        {"vessel_glyph", vesselReport()},
        {"labels", labelsReport()},
        {"slices", slicesReport()},
        {"vessels", vesselsReport()},
        {"crop_handles", cropHandlesReport()},
        {"layout", layout}}},
  };
}

nlohmann::json App::labelsReport() const {
  return {{"voxels", labels_.counted ? nlohmann::json(labels_.voxels) : nlohmann::json(nullptr)},
          {"busy", labels_.job.running()},
          {"dirty", labels_.dirty},
          {"undo", labels_.undo.size()},
          {"redo", labels_.redo.size()},
          {"tiles_built_ahead", labels_.tilesBuiltAhead},
          {"error", labels_.error}};
}

nlohmann::json App::dataReport() const {
  const Volume& v = data_.volume;
  nlohmann::json hu = nullptr;
  if (huRange_) hu = {huOfDensity(huRange_->minDensity), huOfDensity(huRange_->maxDensity)};
  return {{"name", data_.name},
          {"description", data_.description},
          {"dims", {v.dims.x, v.dims.y, v.dims.z}},
          {"spacing", {v.spacing.x, v.spacing.y, v.spacing.z}},
          {"orientation",
           std::string{lpsLetter(v.direction[0]), lpsLetter(v.direction[1]), lpsLetter(v.direction[2])}},
          {"hu_range", hu},
          {"study", studyBanner(data_.study)},
          {"hu_calibrated", huRange_ ? nlohmann::json(huCalibrated_) : nlohmann::json(nullptr)},
          {"loading", load_.running()},
          {"load_error", loadError_},
          {"recent_files", doc().recentFiles},
          {"panels_open", doc().panelsOpen},
          {"session_offered", offeredSession_ ? offeredSession_->dataset : ""},
          {"series_running", seriesJob_.running()},
          {"movie_note", series_.movieNote}};
}

// Where the crop box's handles are on screen, for scripts that drag them.
nlohmann::json App::cropHandlesReport() const {
  nlohmann::json handles = nlohmann::json::array();
  for (const CropHandle& handle : shownCropHandles())
    handles.push_back({{"axis", handle.face.axis},
                       {"at_max", handle.face.atMax},
                       {"at", {handle.screen.x, handle.screen.y}},
                       {"px_per_mm", {handle.screenPerMm.x, handle.screenPerMm.y}}});
  return handles;
}

nlohmann::json App::vesselReport() const {
  const VesselGlyphPanel& vg = vessel_;
  const VesselGlyphState& set = doc().vesselGlyph;
  return {{"enabled", set.enabled},
          {"rendering", scene_ && scene_->hasRegions()},
          {"rendered_paths", scene_ && scene_->hasRegions() ? sceneCenterlines_.paths.size() : 0},
          {"overlay", set.overlay},
          {"centerlines", vg.file},
          {"paths", vg.physical ? vg.physical->paths.size() : 0},
          {"focus", focusSpecText(set.settings.focus)},
          {"context", contextSpecText(set.settings)},
          {"outside", set.outsideRendered ? "main-tf" : "clip"},
          {"cleft", set.settings.cleft},
          {"half_vessel", set.settings.halfVessel},
          {"focus_tf", regionTfName(doc(), TfTarget::focus)},
          {"context_tf", regionTfName(doc(), TfTarget::context)},
          {"tf_editing", tfTargetName(tfTargets_.editing())},
          {"error", vg.error},
          {"problem", vg.problem},
          {"cpr", cprReport()},
          {"hybrid", hybridReport()}};
}

nlohmann::json App::cprReport() const {
  const CprViewPanel& panel = cprView_;
  nlohmann::json hovered = nullptr;
  if (panel.hovered) {
    hovered = {
        {"arc_mm", panel.hovered->arcMm}, {"hu", panel.hovered->hu}, {"path", panel.hovered->path}};
    if (panel.markedOnDvr) hovered["dvr_screen"] = {panel.markedOnDvr->x, panel.markedOnDvr->y};
  }
  nlohmann::json cursor = nullptr;
  if (const std::optional<CprCursor>& set = doc().cpr.cursor) {
    cursor = {{"path", set->path}, {"arc_mm", set->arcMm}};
    if (panel.cursorPixel) cursor["cpr_pixel"] = {panel.cursorPixel->x, panel.cursorPixel->y};
  }
  return {{"shown", cprViewWidth() > 0},
          {"cursor", cursor},
          {"mode", toString(doc().cpr.mode)},
          {"path", doc().cpr.path},
          {"width", panel.cpr ? panel.cpr->layout.width : 0},
          {"height", panel.cpr ? panel.cpr->layout.height : 0},
          {"pixel_mm", panel.cpr ? panel.cpr->layout.pixelMm : 0.0},
          {"error", panel.error},
          {"hovered", hovered}};
}

nlohmann::json App::hybridReport() const {
  const CprState& cpr = doc().cpr;
  return {{"enabled", cpr.hybrid},
          {"rendering", scene_ && scene_->recipe().hybrid.has_value()},
          {"path", cpr.path},
          {"transition_mm", cpr.transitionMm},
          {"colouring", cprColoringName(cpr.coloring)},
          {"problem", vessel_.hybridProblem}};
}

}  // namespace angio
