#pragma once
// The interface between render/series_export.cpp and the movie writer module
// (render/movie_writer_plugin/, OpenCV's VideoWriter), opened when a series first writes a movie
// (io/plugin_module.h): OpenCV's videoio brings FFmpeg and its libraries into the process.
#include <cstdint>
#include <string>

namespace angio {

inline constexpr char kMovieWriterModule[] = "angioray_movie_writer.so";
inline constexpr char kCreateMovieEncoderSymbol[] = "angioray_create_movie_encoder";

// One movie file being written.
class MovieEncoder {
 public:
  virtual ~MovieEncoder() = default;
  // Opens `file` (its extension picks the container) for width x height frames of the codec
  // `fourcc` (four letters) at `fps`; false if that cannot be written.
  virtual bool open(const std::string& file, const char* fourcc, double fps, int width, int height) = 0;
  virtual bool isOpened() const = 0;
  // Adds a frame of the opened size: BGR bytes, rows top to bottom, no padding.
  virtual void write(const std::uint8_t* bgr) = 0;
  // Finishes the file.
  virtual void release() = 0;
};

// Makes an encoder (not yet open); the caller owns it.
using CreateMovieEncoder = MovieEncoder* (*)();

}  // namespace angio
