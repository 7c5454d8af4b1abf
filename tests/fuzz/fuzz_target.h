#pragma once
// The body of every fuzz target: fuzzTarget("NAME", data, size) feeds the bytes to the reader of
// that name (reader_inputs.h, gui_reader_inputs.h) and aborts, so that libFuzzer saves the input,
// if the reader's error message or a warning is not one line naming the input. Crashes, sanitizer
// reports, hangs and running out of memory libFuzzer notices itself.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <itkMultiThreaderBase.h>
#include <itkObject.h>

#include "tests/fuzz/gui_reader_inputs.h"
#include "tests/fuzz/reader_inputs.h"

namespace angio::fuzz {

// The process's scratch folder, in memory (/dev/shm) where there is one; removed at exit.
class ScratchFolder {
 public:
  ScratchFolder() {
    const std::filesystem::path shm = "/dev/shm";
    path_ = (std::filesystem::is_directory(shm) ? shm : std::filesystem::temp_directory_path()) /
            ("angioray-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path_);
    // ITK's warnings would flood the fuzzer's output; one thread keeps runs reproducible.
    itk::Object::GlobalWarningDisplayOff();
    itk::MultiThreaderBase::SetGlobalDefaultNumberOfThreads(1);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline const ReaderTarget& readerTargetNamed(const char* name) {
  for (const ReaderTarget& target : kIoReaderTargets)
    if (std::strcmp(target.name, name) == 0) return target;
  for (const ReaderTarget& target : kGuiReaderTargets)
    if (std::strcmp(target.name, name) == 0) return target;
  throw std::logic_error(std::string("no fuzz target ") + name);
}

inline int fuzzTarget(const char* name, const std::uint8_t* data, std::size_t size) {
  static const ScratchFolder scratch;  // one per process, made on the first input
  static const ReaderTarget& target = readerTargetNamed(name);
  FuzzInput input{std::string(reinterpret_cast<const char*>(data), size), scratch.path(), {}, {}};
  if (const std::string problem = readerProblem(target, input); !problem.empty()) {
    std::fprintf(stderr, "fuzz_%s: %s\n", name, problem.c_str());
    std::abort();
  }
  return 0;
}

}  // namespace angio::fuzz
