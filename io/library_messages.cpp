#include "io/library_messages.h"

#include <cstring>
#include <iostream>
#include <mutex>
#include <streambuf>
#include <string>

#include <gdcmTrace.h>
#include <itkOutputWindow.h>

namespace angio {

namespace {

// A message folded onto one line: line breaks and tabs become single blanks.
std::string foldedLine(const char* text, std::size_t size) {
  std::string line;
  for (std::size_t n = 0; n < size; ++n) {
    const char c = text[n];
    const bool blank = c == '\n' || c == '\r' || c == '\t';
    if (blank && (line.empty() || line.back() == ' ')) continue;
    line += blank ? ' ' : c;
  }
  while (!line.empty() && line.back() == ' ') line.pop_back();
  return line;
}

// std::cerr's buffer once routed: MetaIO (ITK's MetaImage reader) prints its complaints there,
// a line at a time; each line goes to the sink. Our own messages use stdio, not std::cerr.
class SinkStreamBuffer : public std::streambuf {
 public:
  explicit SinkStreamBuffer(LibraryMessageSink sink) : sink_(std::move(sink)) {}

 protected:
  int overflow(int c) override {
    if (c == traits_type::eof()) return traits_type::not_eof(c);
    std::lock_guard lock(mutex_);
    if (c == '\n') {
      flushLine();
    } else if (pending_.size() < 4096) {
      pending_ += char(c);
    }
    return c;
  }
  int sync() override {
    std::lock_guard lock(mutex_);
    flushLine();
    return 0;
  }

 private:
  void flushLine() {
    const std::string line = foldedLine(pending_.data(), pending_.size());
    pending_.clear();
    if (!line.empty() && sink_) sink_(line);
  }
  LibraryMessageSink sink_;
  std::mutex mutex_;
  std::string pending_;
};

class SinkOutputWindow : public itk::OutputWindow {
 public:
  using Pointer = itk::SmartPointer<SinkOutputWindow>;
  static Pointer make(LibraryMessageSink sink) {
    Pointer window = new SinkOutputWindow;
    window->UnRegister();  // ITK's New() idiom: the smart pointer holds the only reference
    window->sink_ = std::move(sink);
    return window;
  }
  void DisplayText(const char* text) override {
    if (!sink_ || !text) return;
    const std::string line = foldedLine(text, std::strlen(text));
    if (!line.empty()) sink_(line);
  }

 private:
  LibraryMessageSink sink_;
};

}  // namespace

LibraryMessageRoute::LibraryMessageRoute(LibraryMessageSink sink)
    : errorBuffer_(std::make_unique<SinkStreamBuffer>(sink)), previousError_(std::cerr.rdbuf()) {
  std::cerr.rdbuf(errorBuffer_.get());
  itk::OutputWindow::SetInstance(SinkOutputWindow::make(std::move(sink)));
  gdcm::Trace::DebugOff();
  gdcm::Trace::WarningOff();
  gdcm::Trace::ErrorOff();
}

LibraryMessageRoute::~LibraryMessageRoute() {
  std::cerr.rdbuf(previousError_);
  itk::OutputWindow::SetInstance(nullptr);
}

LibraryErrorCapture::LibraryErrorCapture() : previous_(std::cerr.rdbuf(&buffer_)) {}

LibraryErrorCapture::~LibraryErrorCapture() { std::cerr.rdbuf(previous_); }

std::string LibraryErrorCapture::text() const {
  const std::string captured = buffer_.str();
  return foldedLine(captured.data(), captured.size());
}

}  // namespace angio
