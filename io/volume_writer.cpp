#include "io/volume_writer.h"

#include <atomic>
#include <string>
#include <system_error>

#include <itkImage.h>
#include <itkImageFileWriter.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include "io/atomic_write.h"
#include "io/input_error.h"
#include "io/lowercase.h"
#include "io/volume_formats.h"

namespace angio {

namespace {

using HuImage = itk::Image<short, 3>;

HuImage::Pointer toHuImage(const Volume& volume) {
  HuImage::RegionType region;
  HuImage::SpacingType spacing;
  HuImage::PointType origin;
  HuImage::DirectionType direction;
  for (int axis = 0; axis < 3; ++axis) {
    region.SetSize(axis, volume.dims[axis]);
    spacing[axis] = volume.spacing[axis];
    origin[axis] = volume.origin[axis];
    for (int row = 0; row < 3; ++row) direction[row][axis] = volume.direction[axis][row];
  }
  auto image = HuImage::New();
  image->SetRegions(region);
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->SetDirection(direction);
  image->Allocate();
  short* hu = image->GetBufferPointer();
  const Voxel* voxels = volume.voxels.data();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, volume.voxelCount(), 1 << 16),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t n = range.begin(); n != range.end(); ++n)
                        hu[n] = short(densityOf(voxels[n]) - kHuOffset);
                    });
  return image;
}

// Writes `image` to `file`; ITK errors become InputErrors naming `target` (the name the user
// gave), with the temporary name in ITK's message replaced by it.
void writeImage(const HuImage* image, VolumeFormat format, const std::filesystem::path& file,
                const std::filesystem::path& target) {
  auto writer = itk::ImageFileWriter<HuImage>::New();
  writer->SetImageIO(makeImageIO(format));
  writer->SetFileName(file.string());
  writer->SetInput(image);
  writer->SetUseCompression(true);  // zlib for MetaImage, gzip for NRRD; NIfTI compresses .nii.gz only
  try {
    writer->Update();
  } catch (const itk::ExceptionObject& error) {
    std::string message = oneLine(error);
    for (auto at = message.find(file.string()); at != std::string::npos;
         at = message.find(file.string(), at))
      message.replace(at, file.string().size(), target.string());
    throw InputError(target, message);
  }
}

bool isDetachedHeader(const std::filesystem::path& path) {
  const std::string extension = lowercase(path.extension().string());
  return extension == ".mhd" || extension == ".nhdr";
}

// .mhd/.nhdr headers name their data file, so the data must be written under its final name: write
// both into a scratch folder beside the target, move the data file(s) into place, then the header
// (atomically), so the header never names data that is not there.
void writeDetached(const HuImage* image, VolumeFormat format, const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path folder = target.parent_path();
  const std::filesystem::path scratch =
      folder / (".angioray-write-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::create_directory(scratch);
  try {
    writeImage(image, format, scratch / target.filename(), target);
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

void writeVolume(const Volume& volume, const std::filesystem::path& path) {
  const auto format = volumeFormatOf(path);
  if (!format)
    throw InputError(path, "unknown volume format '" + path.extension().string() +
                               "' (use .mha, .mhd, .nrrd, .nhdr, .nii or .nii.gz)");
  if (volume.voxelCount() == 0 || volume.voxels.size() != volume.voxelCount())
    throw InputError(path, "cannot write an empty or inconsistent volume");
  try {
    const HuImage::Pointer image = toHuImage(volume);
    if (isDetachedHeader(path)) {
      writeDetached(image, *format, path);
    } else {
      writeAtomically(
          path, [&](const std::filesystem::path& temp) { writeImage(image, *format, temp, path); });
    }
  } catch (const itk::ExceptionObject& error) {  // from building the image (allocation)
    throw InputError(path, oneLine(error));
  } catch (const std::filesystem::filesystem_error& error) {
    throw InputError(path, error.code().message());
  }
}

}  // namespace angio
