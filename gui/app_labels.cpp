// The Labels section in App: automatic bone and table removal and pick-and-grow run in the
// background and end in a LabelChange (gui/label_change.h); applying one (or undoing it) stops
// the renderer and the jobs that read the volume, rewrites the label bits and starts a renderer
// on the changed volume, whose slice tiles then know the new labels (core/slice_tiles.h): built
// ahead in the job for a change over most slices, else refreshed in the renderer's first frame.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>

#include <imgui.h>

#include "core/ray_pick.h"
#include "core/volume_sampling.h"
#include "gui/app.h"
#include "io/input_error.h"
#include "io/volume_reader.h"
#include "render/label_styles.h"
#include "segment/bone_removal.h"
#include "segment/region_growing.h"

namespace angio {

namespace fs = std::filesystem;

namespace {

// A new label's style: hidden for bone and table (what removal is for), shown for the user's.
void addStyle(std::vector<LabelStyle>& styles, int label) {
  for (const LabelStyle& style : styles)
    if (style.label == label) return;
  LabelStyle& style = styleOf(styles, label);
  if (label == kBoneLabel || label == kTableLabel) style.mode = LabelMode::hidden;
}

// The share of bone removal's progress bar that the segmentation takes; building the tiles ahead
// the rest (about 16 s and 1 s at 512x512x1200).
constexpr double kSegmentationShare = 0.94;

// Whether a change's slice tiles are built ahead, in a job, while the renderer still shows the
// volume as it is: for a change over more than half of the slices about `axis` (bone removal, a
// label file, their undo), which the renderer would otherwise summarise again in the first frame
// after it, uncancellable (1.5-2.3 s at 512x512x1200). A smaller change (a grown region) is
// refreshed there in a time proportional to its slices.
bool tilesBuiltAhead(const Volume& volume, Axis axis, const LabelChange& change) {
  return overlaySummarisedAbout(axis) &&
         2 * slicesHolding(volume, axis, change.voxels).size() > std::size_t(volume.dims[int(axis)]);
}

struct JobCancelled {};

// A job's change with the tiles of the volume it leaves (its labels after; with `undo` before)
// when tilesBuiltAhead; they fill the job's progress bar from `progressFrom` on. A cancel meanwhile,
// or too little memory for a second set of tiles, leaves the change without them (the renderer
// refreshes its own then).
LabelJobResult withTilesAhead(const Volume& volume, Axis axis, LabelChange change, JobControl& control,
                              double progressFrom = 0, bool undo = false) {
  if (!tilesBuiltAhead(volume, axis, change)) return {std::move(change), nullptr};
  const auto building = [&control, progressFrom](double fraction) {
    control.progress.store(progressFrom + (1 - progressFrom) * fraction);
    if (control.cancel.load()) throw JobCancelled();
  };
  try {
    const LabelOverlay overlay{change.voxels, undo ? change.before : change.after};
    auto tiles = std::make_shared<SliceTiles>(buildSliceTiles(volume, axis, overlay, building));
    return {std::move(change), std::move(tiles)};
  } catch (const JobCancelled&) {
    return {std::move(change), nullptr};
  } catch (const std::bad_alloc&) {
    return {std::move(change), nullptr};
  }
}

}  // namespace

void App::resetLabels() {
  labels_.job.stop();
  labels_.undo.clear();
  labels_.redo.clear();
  labels_.counted = false;
  labels_.dirty = false;
  labels_.error.clear();
  labels_.counting = std::async(std::launch::async, [this] { return countLabels(data_.volume); });
  if (!labels_.pendingFile.empty()) {
    startLabelRead(labels_.pendingFile);
    labels_.pendingFile.clear();
  }
}

void App::drawLabelsSection() {
  // Closed until opened: the sections below it stay in view on a small screen.
  if (!sectionHeader("Labels", false)) return;
  LabelsPanelInfo info;
  info.hasVolume = data_.volume.voxelCount() > 0;
  info.voxels = labels_.voxels;
  info.counted = labels_.counted;
  info.busy = labels_.job.running();
  info.busyWhat = labels_.jobWhat;
  info.progress = labels_.job.progress();
  info.canUndo = !labels_.undo.empty();
  info.canRedo = !labels_.redo.empty();
  if (info.canUndo) info.undoWhat = labels_.undo.back().what;
  if (info.canRedo) info.redoWhat = labels_.redo.back().what;
  info.file = doc().labels.file.empty() ? "" : doc().labels.file + (labels_.dirty ? " (changed)" : "");
  info.error = labels_.error;
  const LabelsPanelResult result = drawLabelsPanel(doc(), labels_.ui, info, widgetRects_);
  commit(result.edit);
  if (result.cancel) labels_.job.cancel();
  if (result.removeBoneAndTable) startBoneRemoval();
  if (result.undo && !labels_.undo.empty()) stepLabels(true);
  if (result.redo && !labels_.redo.empty()) stepLabels(false);
  if (result.save) saveLabels(labels_.ui.path);
  if (result.load) startLabelRead(labels_.ui.path);
  if (result.browse) browseFor(BrowserPurpose::labelsFile, labels_.ui.path);
}

// Undo or redo the last change: at once, or for a change whose tiles are built ahead, in a job
// that builds them first (the change waits there, off both stacks, until it is applied).
void App::stepLabels(bool undo) {
  std::vector<LabelChange>& from = undo ? labels_.undo : labels_.redo;
  auto change = std::make_shared<LabelChange>(std::move(from.back()));
  from.pop_back();
  const Axis axis = doc().view.axis;
  if (!tilesBuiltAhead(data_.volume, axis, *change)) {
    changeLabels(*change, undo);
    message_ = (undo ? "undid " : "redid ") + change->what;
    (undo ? labels_.redo : labels_.undo).push_back(std::move(*change));
    return;
  }
  labels_.error.clear();
  labels_.jobWhat = (undo ? "undoing " : "redoing ") + change->what;
  labels_.jobStep = undo ? LabelStep::undo : LabelStep::redo;
  labels_.fileRead.clear();
  labels_.job.start([this, axis, undo, change](JobControl& control) {
    return withTilesAhead(data_.volume, axis, std::move(*change), control, 0, undo);
  });
}

// An undo or redo job's end: the change applied with its tiles, or back on its stack if cancelled.
void App::finishLabelStep(LabelJobResult result, bool cancelled) {
  const bool undo = labels_.jobStep == LabelStep::undo;
  if (cancelled) {
    (undo ? labels_.undo : labels_.redo).push_back(std::move(result.change));
    message_ = labels_.jobWhat + " cancelled";
    return;
  }
  changeLabels(result.change, undo, std::move(result.tiles));
  message_ = (undo ? "undid " : "redid ") + result.change.what;
  (undo ? labels_.redo : labels_.undo).push_back(std::move(result.change));
}

void App::startBoneRemoval() {
  std::optional<Centerlines> protect;
  try {
    if (const Centerlines* framed = framedCenterlines()) protect = *framed;
  } catch (const std::exception&) {
    // Centerlines that do not fit the dataset protect nothing; the VesselGlyph panel says why.
  }
  labels_.error = calibrationWarning(data_.volume);  // shown while it runs, and after
  labels_.jobWhat = "removing bone and table";
  labels_.jobStep = LabelStep::change;
  labels_.fileRead.clear();
  const Axis axis = doc().view.axis;
  labels_.job.start([this, axis, protect = std::move(protect)](JobControl& control) {
    SegmentationProgress progress;
    progress.progress = [&control](double fraction) {
      control.progress.store(kSegmentationShare * fraction);
    };
    progress.cancel = &control.cancel;
    const LabelResult result =
        removeBoneAndTable(data_.volume, protect ? &*protect : nullptr, {}, progress);
    if (result.cancelled) return LabelJobResult{};
    return withTilesAhead(data_.volume, axis,
                          changeTo(data_.volume, result.labels, "bone and table removal"), control,
                          kSegmentationShare);
  });
}

void App::growOnClick() {
  if (!labels_.ui.growTool || labels_.job.running()) return;
  const std::optional<glm::dvec2> imagePoint = clickedImagePoint();
  if (!imagePoint) return;
  const bool giveBack = labels_.ui.target == GrowTarget::unlabel;
  const std::optional<PickedPoint> picked =
      giveBack ? pickLabelled(data_.volume, shown_->params, *imagePoint) : pickVisible(*imagePoint);
  if (!picked) {
    message_ = giveBack ? "no labelled voxel under the cursor" : "nothing visible under the cursor";
    return;
  }
  const glm::ivec3 seed = nearestVoxel(data_.volume, picked->positionMm / data_.volume.spacing);
  GrowSettings settings{labels_.ui.lowHu, labels_.ui.highHu, labels_.ui.growLabel, labels_.ui.fillHoles};
  labels_.error.clear();
  labels_.fileRead.clear();
  labels_.jobWhat = giveBack ? "giving back" : "growing";
  labels_.jobStep = LabelStep::change;
  const Axis axis = doc().view.axis;
  labels_.job.start([this, seed, settings, giveBack, axis](JobControl& control) {
    if (giveBack)
      return withTilesAhead(
          data_.volume, axis,
          changeOf(data_.volume, connectedLabelled(data_.volume, seed, &control.cancel), 0, "give back"),
          control);
    return withTilesAhead(
        data_.volume, axis,
        changeOf(data_.volume, growRegion(data_.volume, seed, settings, &control.cancel), settings.label,
                 "grow " + defaultLabelName(settings.label)),
        control);
  });
}

void App::startLabelRead(const std::string& file) {
  labels_.error.clear();
  labels_.jobWhat = "reading " + fs::path(file).filename().string();
  labels_.fileRead = file;
  labels_.jobStep = LabelStep::change;
  const Axis axis = doc().view.axis;
  labels_.job.start([this, file, axis](JobControl& control) {
    ReadOptions options;
    options.warn = printWarning;
    return withTilesAhead(
        data_.volume, axis,
        changeTo(data_.volume, readLabels(file, data_.volume, options), "load " + file), control);
  });
}

void App::saveLabels(const std::string& file) {
  try {
    writeLabelFile(file, data_.volume, doc().tf.labels, labels_.voxels);
    commit(LabelFileEdit{fs::absolute(file).lexically_normal().string()});
    labels_.dirty = false;
    message_ = "saved labels " + file;
  } catch (const std::exception& error) {
    labels_.error = error.what();
  }
}

void App::pollLabelJobs() {
  if (labels_.counting.valid() &&
      labels_.counting.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    labels_.voxels = labels_.counting.get();
    labels_.counted = true;
  }
  if (!labels_.job.ready()) return;
  const bool cancelled = labels_.job.cancelRequested();
  try {
    LabelJobResult result = labels_.job.take();
    if (labels_.jobStep != LabelStep::change) return finishLabelStep(std::move(result), cancelled);
    LabelChange& change = result.change;
    if (cancelled) {
      message_ = labels_.jobWhat + " cancelled";
      return;
    }
    if (!labels_.fileRead.empty())
      commit(LabelFileEdit{fs::absolute(labels_.fileRead).lexically_normal().string()});
    if (change.empty()) {
      message_ = labels_.jobWhat + ": no voxel changed";
      return;
    }
    changeLabels(change, false, std::move(result.tiles));
    labels_.dirty = labels_.fileRead.empty();
    message_ = change.what + ": " + std::to_string(change.voxels.size()) + " voxels";
    labels_.undo.push_back(std::move(change));
    labels_.redo.clear();
  } catch (const std::exception& error) {
    labels_.error = error.what();
  }
}

void App::changeLabels(const LabelChange& change, bool undo, std::shared_ptr<SliceTiles> tilesAfter) {
  rendererSince_ = Clock::now();
  seriesJob_.stop();
  cprView_.job.stop();
  vessels_.job.stop();  // the tracer reads the label bits
  if (export_.job.valid()) export_.job.wait();
  // Joins its worker (nothing reads the voxels now); the next renderer refreshes the slices of
  // its tiles the change touched, not the whole volume's (a grown region: a few of them).
  TilesAhead tiles = renderer_->stopAndReleaseTiles();
  renderer_.reset();
  lastRequest_.reset();
  requestTimes_.clear();  // the old renderer's ids: the new one counts from 1 again
  latency_.restart();
  apply(change, undo, data_.volume, labels_.voxels);
  labels_.tilesBuiltAhead = tilesAfter != nullptr;
  if (tilesAfter) tiles = TilesAhead{std::move(tilesAfter), {}};
  else if (tiles.tiles) tiles.markStale(slicesHolding(data_.volume, tiles.tiles->axis, change.voxels));
  data_.tiles = std::move(tiles);
  labels_.dirty = true;
  std::uint16_t present = 0;  // the labels the change gives
  for (const std::uint8_t label : undo ? change.before : change.after)
    present |= std::uint16_t(1u << label);
  std::vector<LabelStyle> styles = doc().tf.labels;
  for (int label = 1; label <= kMaxLabel; ++label)
    if (present & (1u << label)) addStyle(styles, label);
  commit(LabelStylesEdit{styles, doc().labels.showRemoved});
  renderer_ = makeRenderer();
}

std::optional<UnsavedLabels> App::unsavedLabels() const {
  if (!labels_.dirty) return std::nullopt;
  return UnsavedLabels{doc().tf.labels, labels_.voxels};
}

std::string App::exportLabelFile() const {
  if (labels_.dirty || doc().labels.file.empty()) return "";
  return doc().labels.file;
}

}  // namespace angio
