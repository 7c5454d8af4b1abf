// The movie writer module: OpenCV's VideoWriter behind render/movie_writer_plugin.h, so that
// videoio and FFmpeg enter the process only when a movie is written (io/plugin_module.h).
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "render/movie_writer_plugin.h"

namespace {

class OpenCvMovieEncoder : public angio::MovieEncoder {
 public:
  bool open(const std::string& file, const char* fourcc, double fps, int width, int height) override {
    size_ = cv::Size(width, height);
    return writer_.open(file, cv::VideoWriter::fourcc(fourcc[0], fourcc[1], fourcc[2], fourcc[3]), fps,
                        size_);
  }
  bool isOpened() const override { return writer_.isOpened(); }
  void write(const std::uint8_t* bgr) override {
    // A view of the caller's bytes, not a copy (Mat's constructor does not write through it).
    writer_.write(cv::Mat(size_, CV_8UC3, const_cast<std::uint8_t*>(bgr)));
  }
  void release() override { writer_.release(); }

 private:
  cv::Size size_;
  cv::VideoWriter writer_;
};

}  // namespace

extern "C" __attribute__((visibility("default"))) angio::MovieEncoder* angioray_create_movie_encoder() {
  return new OpenCvMovieEncoder;
}
