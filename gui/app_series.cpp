// "Export rotation series" in the Export section of App: the settings (gui/panel_export.h), and
// the series rendered by exportRotationSeries (render/series_export.h) in a BackgroundJob.
#include <filesystem>

#include "gui/app.h"
#include "gui/app_export.h"
#include "gui/panel_export.h"

namespace angio {

void App::drawSeriesExport() {
  const auto exportOpen = doc().panelsOpen.find("Export");
  if (exportOpen == doc().panelsOpen.end() || !exportOpen->second) return;
  JobInfo job;
  job.running = seriesJob_.running();
  job.progress = seriesJob_.progress();
  job.cancelRequested = seriesJob_.cancelRequested();
  const ExportRequests requests = angio::drawSeriesExport(series_, job, widgetRects_);
  if (requests.cancel) seriesJob_.cancel();
  if (requests.browse) browseFor(BrowserPurpose::seriesFolder, series_.folder);
  if (!requests.start) return;
  seriesJob_.start([this, base = exportRecipe(), centerlines = exportCenterlines(), spec = series_.spec,
                    folder = series_.folder, labels = unsavedLabels(),
                    traced = unsavedCenterlines()](JobControl& control) {
    RenderRecipe recipe = base;
    if (labels || traced) std::filesystem::create_directories(folder);
    if (labels)
      saveLabelsFor(recipe, data_.volume, *labels, std::filesystem::path(folder) / "labels.seg.nrrd");
    Centerlines used = centerlines;
    if (traced)
      used = saveCenterlinesFor(
          recipe, data_.volume, *traced,
          std::filesystem::path(folder) / ("vessels" + std::string(kBesideCenterlines)));
    SeriesCallbacks callbacks;
    callbacks.cancel = &control.cancel;
    callbacks.progress = [&control](int done, int total) {
      control.progress.store(double(done) / total);
    };
    return exportRotationSeries(data_.volume, used, recipe, spec, folder, callbacks);
  });
  message_ = "exporting a rotation series to " + series_.folder;
}

}  // namespace angio
