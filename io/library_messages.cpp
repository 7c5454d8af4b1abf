#include "io/library_messages.h"

#include <gdcmTrace.h>
#include <itkOutputWindow.h>

namespace angio {

namespace {

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
    std::string line;
    for (const char* c = text; *c; ++c) {
      const bool blank = *c == '\n' || *c == '\r' || *c == '\t';
      if (blank && (line.empty() || line.back() == ' ')) continue;
      line += blank ? ' ' : *c;
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    if (!line.empty()) sink_(line);
  }

 private:
  LibraryMessageSink sink_;
};

}  // namespace

void routeLibraryMessages(LibraryMessageSink sink) {
  itk::OutputWindow::SetInstance(SinkOutputWindow::make(std::move(sink)));
  gdcm::Trace::DebugOff();
  gdcm::Trace::WarningOff();
  gdcm::Trace::ErrorOff();
}

}  // namespace angio
