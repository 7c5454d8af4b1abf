#include "io/atomic_write.h"

#include <atomic>
#include <string>

#include <unistd.h>

#include "io/input_error.h"

namespace angio {

namespace {

std::filesystem::path temporaryName(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  // "name.tmp-<pid>-<n>.ext": unique per process and call; the extension is kept last, and for
  // double extensions (.nii.gz) the whole suffix after the first dot of the file name is kept.
  const std::string file = target.filename().string();
  const auto dot = file.find('.', 1);
  const std::string stem = dot == std::string::npos ? file : file.substr(0, dot);
  const std::string extension = dot == std::string::npos ? "" : file.substr(dot);
  return target.parent_path() /
         (stem + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + extension);
}

}  // namespace

void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& tempPath)>& write) {
  const std::filesystem::path temp = temporaryName(target);
  try {
    write(temp);
    std::filesystem::rename(temp, target);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw;
  }
}

}  // namespace angio
