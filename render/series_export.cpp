#include "render/series_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "core/slice_tiles.h"
#include "core/view_geometry.h"
#include "render/export.h"
#include "render/frame_renderer.h"
#include "render/movie_writer_plugin.h"
#include "io/input_error.h"
#include "io/plugin_module.h"

namespace angio {

namespace fs = std::filesystem;

namespace {

// The movie: H.264 in an MP4 where OpenCV's FFmpeg has an H.264 encoder (Debian's: x264), else
// MPEG-4 part 2 ('mp4v') in an MP4, else MJPG in an AVI; the note says which. The frame is the
// first image's size rounded up to even (H.264's 4:2:0 chroma needs even sides; x264 writes a
// broken file for odd ones), images placed top-left on black. It is written under a temporary
// name and renamed over PREFIX.mp4 on close(), so a series that fails half-way leaves a movie the
// user had as it was. The encoder is the movie writer module's (render/movie_writer_plugin.h).
class MovieWriter {
 public:
  MovieWriter(const fs::path& folder, const std::string& prefix, double fps, int width, int height)
      : width_(width + width % 2), height_(height + height % 2), writer_(createEncoder()) {
    struct Choice {
      const char* extension;
      const char* fourcc;
      const char* note;
    };
    const Choice choices[] = {
        {".mp4", "avc1", "MP4 (H.264)"}, {".mp4", "mp4v", "MP4 (mp4v)"}, {".avi", "MJPG", "AVI (MJPG)"}};
    for (const Choice& choice : choices) {
      path_ = folder / (prefix + choice.extension);
      writing_ = folder / (prefix + ".partial" + choice.extension);  // the extension picks the container
      if (writer_->open(writing_.string(), choice.fourcc, fps, width_, height_)) {
        note_ = choice.note;
        return;
      }
      std::error_code ignored;
      fs::remove(writing_, ignored);
    }
    path_.clear();
    writing_.clear();
    note_ = "no movie: OpenCV's VideoWriter opens none of H.264, mp4v and MJPG";
  }

  bool open() const { return writer_->isOpened(); }
  const fs::path& path() const { return path_; }
  const std::string& note() const { return note_; }

  void add(const Image& image) {
    const std::vector<std::uint8_t> rgb = toRgb8(image);
    std::vector<std::uint8_t> frame(std::size_t(width_) * height_ * 3, 0);  // black
    for (int y = 0; y < std::min(image.height, height_); ++y)
      for (int x = 0; x < std::min(image.width, width_); ++x) {
        const std::uint8_t* p = &rgb[(std::size_t(y) * image.width + x) * 3];
        std::uint8_t* q = &frame[(std::size_t(y) * width_ + x) * 3];
        q[0] = p[2];  // OpenCV wants BGR
        q[1] = p[1];
        q[2] = p[0];
      }
    writer_->write(frame.data());
  }

  // The movie under its name; on failure the note says why and no movie is left.
  void close() {
    if (!writer_->isOpened()) return;
    writer_->release();
    std::error_code error;
    fs::rename(writing_, path_, error);
    if (!error) return;
    note_ = "no movie: cannot rename " + writing_.filename().string() + ": " + error.message();
    fs::remove(writing_, error);
    path_.clear();
  }

  ~MovieWriter() {  // not closed: the series failed; its part-written movie goes
    if (!writer_->isOpened()) return;
    writer_->release();
    std::error_code ignored;
    fs::remove(writing_, ignored);
  }
  MovieWriter(const MovieWriter&) = delete;
  MovieWriter& operator=(const MovieWriter&) = delete;

 private:
  static std::unique_ptr<MovieEncoder> createEncoder() {
    const auto create =
        pluginFunction<CreateMovieEncoder>(kMovieWriterModule, kCreateMovieEncoderSymbol);
    return std::unique_ptr<MovieEncoder>(create());
  }

  int width_;
  int height_;
  std::unique_ptr<MovieEncoder> writer_;
  fs::path path_;     // PREFIX.mp4 / .avi
  fs::path writing_;  // PREFIX.partial.mp4 / .avi until close()
  std::string note_;
};

std::string numbered(const SeriesSpec& spec, int index) {
  const int digits = std::max(3, int(std::to_string(spec.count - 1).size()));
  char number[16];
  std::snprintf(number, sizeof number, "%0*d", digits, index);
  return spec.prefix + "-" + number + "." + spec.format;
}

void checkSpec(const SeriesSpec& spec, const fs::path& folder) {
  if (spec.count < 1 || spec.count > 100000)
    throw InputError(folder, "the number of views must be 1 .. 100000");
  if (!std::isfinite(spec.startDeg) || !std::isfinite(spec.arcDeg) || std::abs(spec.arcDeg) > 360)
    throw InputError(folder, "the arc must be within -360 .. 360 degrees");
  if (spec.format != "png" && spec.format != "tif")
    throw InputError(folder, "series format must be png or tif, not " + spec.format);
  if (spec.prefix.empty() || spec.prefix.find('/') != std::string::npos)
    throw InputError(folder, "the file prefix must be a plain name");
  if (spec.movie && !(spec.movieFps > 0 && spec.movieFps <= 120))
    throw InputError(folder, "movie frames per second must be in (0, 120]");
}

}  // namespace

std::vector<double> seriesAngles(double startDeg, double arcDeg, int count) {
  const bool fullTurn = std::abs(std::abs(arcDeg) - 360) < 1e-9;
  const double step = count <= 1 ? 0 : fullTurn ? arcDeg / count : arcDeg / (count - 1);
  std::vector<double> angles;
  for (int n = 0; n < count; ++n) angles.push_back(wrapDegrees(startDeg + n * step));
  return angles;
}

SeriesResult exportRotationSeries(const Volume& volume, const Centerlines& centerlines,
                                  const RenderRecipe& base, const SeriesSpec& spec,
                                  const fs::path& folder, const SeriesCallbacks& callbacks) {
  checkSpec(spec, folder);
  std::error_code error;
  fs::create_directories(folder, error);
  if (error || !fs::is_directory(folder))
    throw InputError(folder, "cannot create the folder" + (error ? ": " + error.message() : ""));
  const auto cancelled = [&] { return callbacks.cancel && callbacks.cancel->load(); };

  // One scene and one frame renderer for every view: the tables, tubes and slice tiles are shared.
  FrameRenderer renderer(volume);
  const std::shared_ptr<const PreparedScene> scene = PreparedScene::prepare(volume, centerlines, base);
  const std::vector<double> angles = seriesAngles(spec.startDeg, spec.arcDeg, spec.count);

  // The views and their sidecars replace an earlier series only once all of them are written.
  AtomicFileGroup files;
  SeriesResult result;
  std::unique_ptr<MovieWriter> movie;
  for (int n = 0; n < spec.count && !result.cancelled; ++n) {
    RenderRecipe sidecar = base;
    sidecar.params.angleDeg = angles[n];
    checkImageSize(makeViewGeometry(volume, sidecar.params), folder);
    FastRenderStats stats;
    const Image image = renderer.render(scene, sidecar.params, {.cancel = callbacks.cancel}, &stats);
    if (stats.cancelled || cancelled()) {
      result.cancelled = true;
      break;
    }
    const fs::path file = folder / numbered(spec, n);
    addImageAndSidecar(files, image, file, sidecar);
    result.images.push_back(file);
    if (spec.movie && !movie)
      movie =
          std::make_unique<MovieWriter>(folder, spec.prefix, spec.movieFps, image.width, image.height);
    if (movie && movie->open()) movie->add(image);
    if (callbacks.progress) callbacks.progress(n + 1, spec.count);
  }
  if (result.cancelled) {  // nothing of it is written; the part-written movie goes with `movie`
    result.images.clear();
    result.summary = "cancelled: nothing written to " + folder.string();
    return result;
  }
  files.commit();
  if (movie) {
    movie->close();
    result.movieNote = movie->note();
    if (!movie->path().empty() && fs::exists(movie->path())) result.movie = movie->path();
  } else if (spec.movie) {
    result.movieNote = "no movie: no views were rendered";
  }
  char summary[512];
  std::snprintf(summary, sizeof summary, "exported %zu of %d views to %s%s%s", result.images.size(),
                spec.count, folder.string().c_str(), result.movie.empty() ? "" : " + ",
                result.movie.empty() ? "" : result.movie.filename().string().c_str());
  result.summary = summary;
  return result;
}

}  // namespace angio
