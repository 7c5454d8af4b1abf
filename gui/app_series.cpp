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
  if (!requests.start) return;
  seriesJob_.start([this, base = exportRecipe(), centerlines = exportCenterlines(), spec = series_.spec,
                    folder = series_.folder, labels = unsavedLabels()](JobControl& control) {
    RenderRecipe recipe = base;
    if (labels) {
      std::filesystem::create_directories(folder);
      saveLabelsFor(recipe, data_.volume, *labels, std::filesystem::path(folder) / "labels.seg.nrrd");
    }
    SeriesCallbacks callbacks;
    callbacks.cancel = &control.cancel;
    callbacks.progress = [&control](int done, int total) {
      control.progress.store(double(done) / total);
    };
    return exportRotationSeries(data_.volume, centerlines, recipe, spec, folder, callbacks);
  });
  message_ = "exporting a rotation series to " + series_.folder;
}

}  // namespace angio
