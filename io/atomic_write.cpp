#include "io/atomic_write.h"

#include <atomic>
#include <fstream>
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

void writeBytesAtomically(const std::filesystem::path& target, const std::string& bytes) {
  try {
    writeAtomically(target, [&](const std::filesystem::path& temp) {
      std::ofstream out(temp, std::ios::binary | std::ios::trunc);
      if (!out) throw InputError(target, "cannot open for writing");
      out << bytes;
      out.close();
      if (!out) throw InputError(target, "write failed");
    });
  } catch (const std::filesystem::filesystem_error& error) {
    // The rename over the target failed (a folder of that name, another file system).
    throw InputError(target, "cannot write: " + error.code().message());
  }
}

}  // namespace angio
