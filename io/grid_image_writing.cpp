#include "io/grid_image_writing.h"

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include <stdlib.h>

#include "io/atomic_write.h"
#include "io/lowercase.h"

namespace angio {

namespace {

bool isDetachedHeader(const std::filesystem::path& path) {
  const std::string extension = lowercase(path.extension().string());
  return extension == ".mhd" || extension == ".nhdr";
}

// A new empty folder beside `target` (mkdtemp makes the name unique across processes and calls).
std::filesystem::path makeScratchFolder(const std::filesystem::path& target) {
  std::string name = (target.parent_path() / ".angioray-write-XXXXXX").string();
  if (!::mkdtemp(name.data()))
    throw std::filesystem::filesystem_error("cannot create a scratch folder", name,
                                            std::error_code(errno, std::generic_category()));
  return name;
}

// .mhd/.nhdr headers name their data file, so the data must be written under its final name:
// write both into a scratch folder beside the target, move the data file(s) into place, then the
// header (atomically), so the header never names data that is not there.
void writeDetached(const std::filesystem::path& target,
                   const std::function<void(const std::filesystem::path& file)>& write) {
  const std::filesystem::path folder = target.parent_path();
  const std::filesystem::path scratch = makeScratchFolder(target);
  try {
    write(scratch / target.filename());
    for (const auto& entry : std::filesystem::directory_iterator(scratch))
      if (entry.path().filename() != target.filename())
        std::filesystem::rename(entry.path(), folder / entry.path().filename());
    writeAtomically(target, [&](const std::filesystem::path& temp) {
      std::filesystem::rename(scratch / target.filename(), temp);
    });
    std::filesystem::remove_all(scratch);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove_all(scratch, ignored);
    throw;
  }
}

}  // namespace

VolumeFormat requireWritableVolume(const Volume& volume, const std::filesystem::path& target) {
  const auto format = volumeFormatOf(target);
  if (!format)
    throw InputError(target, "unknown volume format '" + target.extension().string() +
                                 "' (use .mha, .mhd, .nrrd, .nhdr, .nii or .nii.gz)");
  if (volume.voxelCount() == 0 || volume.voxels.size() != volume.voxelCount())
    throw InputError(target, "cannot write an empty or inconsistent volume");
  return *format;
}

void writeVolumeFileAtomically(const std::filesystem::path& target,
                               const std::function<void(const std::filesystem::path& file)>& write) {
  try {
    if (isDetachedHeader(target)) {
      writeDetached(target, write);
    } else {
      writeAtomically(target, write);
    }
  } catch (const std::filesystem::filesystem_error& error) {
    throw InputError(target, error.code().message());
  }
}

InputError volumeWriteError(const itk::ExceptionObject& error, const std::filesystem::path& file,
                            const std::filesystem::path& target) {
  std::string message = oneLine(error);
  for (auto at = message.find(file.string()); at != std::string::npos;
       at = message.find(file.string(), at))
    message.replace(at, file.string().size(), target.string());
  return InputError(target, message);
}

}  // namespace angio
