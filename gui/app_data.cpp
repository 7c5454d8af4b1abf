// Datasets in App: open a volume file or DICOM folder (the Data section's file browser and recent
// files, gui/panel_data.h; drag-and-drop, scripts), load it in the background with progress and
// cancel, replace the dataset on success, keep the previous one and show a dismissable error on
// failure.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "gui/app.h"
#include "gui/panel_data.h"
#include "gui/viewport.h"
#include "io/input_error.h"
#include "io/tf_file.h"
#include "io/volume_reader.h"

namespace angio {

namespace fs = std::filesystem;

namespace {

// The share of a load's progress bar that reading takes; building the slice tiles the rest
// (about 2.8 s and 0.5 s at 512x512x1200).
constexpr double kReadShare = 0.85;

// Reads the volume, then builds its slice tiles for `axis`; both report progress and stop on cancel.
LoadedDataset loadInBackground(const std::string& path, Axis axis, JobControl& control) {
  const auto report = [&control](double fraction) {
    control.progress.store(fraction);
    if (control.cancel.load()) throw LoadCancelled();
  };
  ReadOptions read;
  read.progress = [&report](double fraction) { report(kReadShare * fraction); };
  read.warn = printWarning;
  LoadedDataset dataset = loadedDataset(readVolume(path, read), path);
  dataset.tiles.tiles =
      std::make_shared<SliceTiles>(buildSliceTiles(dataset.volume, axis, [&report](double fraction) {
        report(kReadShare + (1 - kReadShare) * fraction);
      }));
  return dataset;
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

}  // namespace

LoadedDataset loadedDataset(LoadedVolume loaded, const std::string& name) {
  return LoadedDataset{std::move(loaded.volume), name, std::move(loaded.description),
                       std::move(loaded.study)};
}

void App::openDataset(const std::string& path, bool ofSession) {
  if (path.empty()) return;
  if (load_.running()) {
    message_ = "still loading " + loadPath_ + "; cancel it first";
    return;
  }
  loadPath_ = absoluteDataset(path);  // a missing one stays as given: the load names it
  loadOfSession_ = ofSession;
  loadError_.clear();
  const Axis axis = pendingSession_ ? pendingSession_->view.axis : doc().view.axis;
  load_.start(
      [path = loadPath_, axis](JobControl& control) { return loadInBackground(path, axis, control); });
  message_ = "loading " + loadPath_;
}

bool App::backgroundBusy() const {
  return load_.running() || seriesJob_.running() || vessel_.load.running() || cprView_.job.running() ||
         labels_.job.running() || labels_.counting.valid() || vessels_.job.running() ||
         !vessels_.queued.empty();
}

void App::pollBackgroundJobs() {
  if (load_.ready()) {
    try {
      const double seconds = load_.seconds();
      const std::vector<std::string> dropped =
          loadOfSession_ ? std::vector<std::string>{} : droppedByNewDataset(doc());
      replaceDataset(load_.take());
      char took[32];
      std::snprintf(took, sizeof took, " (%.2f s)", seconds);
      message_ = "opened " + loadPath_ + took;
      if (!dropped.empty()) message_ += "; dropped with the old dataset: " + joined(dropped);
      if (const std::string tf = loadOfSession_ ? "" : resetTfForNewDataset(); !tf.empty())
        message_ += "; " + tf;
      if (pendingSession_) commitSession(*std::exchange(pendingSession_, std::nullopt));
    } catch (const LoadCancelled&) {
      message_ = "loading " + loadPath_ + " cancelled" +
                 (pendingSession_ ? "; the session was not applied" : "");
    } catch (const std::exception& error) {
      loadError_ = error.what() + std::string(pendingSession_ ? " (the session was not applied)" : "");
      message_.clear();
    }
    pendingSession_.reset();
  }
  pollCenterlineLoad();  // after the dataset: centerlines are checked against the one shown
  if (seriesJob_.ready()) {
    try {
      const SeriesResult result = seriesJob_.take();
      message_ = result.summary;
      series_.movieNote = result.movieNote;
    } catch (const std::exception& error) {
      message_ = error.what();
    }
  }
}

// The renderer, the histogram job and the exports read the volume: all stop before it goes.
void App::replaceDataset(LoadedDataset dataset) {
  seriesJob_.stop();
  cprView_.job.stop();  // it reads the old volume
  cprView_.computing.reset();
  if (export_.cancel) export_.cancel->store(true);
  if (export_.job.valid()) export_.job.wait();
  export_.job = {};
  if (histogramJob_.valid()) histogramJob_.wait();
  histogramJob_ = {};
  resetTracer();  // it reads the old volume
  rendererSince_ = Clock::now();
  renderer_.reset();
  shown_.reset();
  incoming_.reset();
  lastRequest_.reset();
  requestTimes_.clear();
  latency_.restart();
  lastFirstLevel_.reset();  // the new volume's cost is its own
  motionIsd_.reset();
  data_ = std::move(dataset);
  commit(DatasetOpened{data_.name, loadOfSession_});
  if (!loadOfSession_) {
    vessel_.ui.path.clear();  // the VesselGlyph section's centerline field named the old file
    dropCenterlines();
  }
  const TfEditorView unzoomed;  // the editor's HU zoom was for the old data
  tfPanel_.editor.huMin = unzoomed.huMin;
  tfPanel_.editor.huMax = unzoomed.huMax;
  histogram_.clear();
  huRange_.reset();
  scene_.reset();  // of the old volume
  renderer_ = makeRenderer();
  resetLabels();
  resetVessels();
  resetSliceView();
  histogramJob_ = std::async(std::launch::async, [this] { return densityHistogram(data_.volume); });
}

// An edited main TF was fitted to the old data: the start preset replaces it, one undo step away.
std::string App::resetTfForNewDataset() {
  if (!doc().tfPreset.empty() || startPreset_.empty()) return "";
  if (tfTargets_.editing() != TfTarget::main) switchTfTarget(TfTarget::main);
  try {
    applyTf(loadPresetOrFile(startPreset_), startPreset_);
  } catch (const std::exception& error) {
    return error.what();
  }
  return "the edited TF gave way to " + startPreset_ + " (Undo brings it back)";
}

void App::drawDataSection() {
  drawSessionBanner();
  drawBrowser();
  if (!sectionHeader("Data")) return;
  DataPanelInfo info;
  info.volume = &data_.volume;
  info.name = data_.name;
  info.description = data_.description;
  info.study = data_.study;
  info.densities = huRange_;
  info.huCalibrated = huCalibrated_;
  info.loading = load_.running();
  info.loadProgress = load_.progress();
  info.loadSeconds = load_.seconds();
  info.cancelRequested = load_.cancelRequested();
  info.loadPath = loadPath_;
  info.loadError = loadError_;
  const DataPanelRequests requests = drawDataPanel(doc(), info, widgetRects_);
  if (requests.browse) browseFor(BrowserPurpose::openVolume, loadPath_.empty() ? data_.name : loadPath_);
  if (requests.open) openDataset(*requests.open);
  if (requests.cancelLoad) load_.cancel();
  if (requests.dismissError) loadError_.clear();
}

}  // namespace angio
