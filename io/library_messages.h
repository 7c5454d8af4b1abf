#pragma once
// ITK and GDCM report what they meet by printing to stderr themselves, several lines at a time,
// around the one line our InputError gives. The program routes them at start to a sink; what they
// find wrong reaches us again as an ITK exception, which io/ turns into an InputError.
#include <functional>
#include <memory>
#include <sstream>
#include <streambuf>
#include <string>

namespace angio {

using LibraryMessageSink = std::function<void(const std::string& oneLine)>;

// While it lives, library messages go to the sink: ITK's output window (process-wide by ITK's
// design) and std::cerr (MetaIO prints there; our own messages use stdio) hand over each message
// folded to one line; GDCM's trace is off. One, held by main.
class LibraryMessageRoute {
 public:
  explicit LibraryMessageRoute(LibraryMessageSink sink);
  ~LibraryMessageRoute();
  LibraryMessageRoute(const LibraryMessageRoute&) = delete;
  LibraryMessageRoute& operator=(const LibraryMessageRoute&) = delete;

 private:
  std::unique_ptr<std::streambuf> errorBuffer_;
  std::streambuf* previousError_;
};

// While it lives, what libraries print on std::cerr is kept here instead of going to the route:
// MetaIO reports a failed decompression only there, then returns as if it had read the voxels.
// The previous buffer is restored after. Not for two threads at once (std::cerr is one stream).
class LibraryErrorCapture {
 public:
  LibraryErrorCapture();
  ~LibraryErrorCapture();
  LibraryErrorCapture(const LibraryErrorCapture&) = delete;
  LibraryErrorCapture& operator=(const LibraryErrorCapture&) = delete;

  // What was printed, folded onto one line; empty if nothing.
  std::string text() const;

 private:
  std::stringbuf buffer_;
  std::streambuf* previous_;
};

}  // namespace angio
