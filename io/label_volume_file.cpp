#include "io/label_volume_file.h"

#include <cstdint>
#include <string>

#include <itkImage.h>
#include <itkImageFileWriter.h>

#include "io/atomic_write.h"
#include "io/input_error.h"
#include "io/lowercase.h"
#include "io/volume_formats.h"

namespace angio {

namespace {

using LabelImage = itk::Image<std::uint8_t, 3>;

LabelImage::Pointer toLabelImage(const Volume& volume) {
  LabelImage::RegionType region;
  LabelImage::SpacingType spacing;
  LabelImage::PointType origin;
  LabelImage::DirectionType direction;
  for (int axis = 0; axis < 3; ++axis) {
    region.SetSize(axis, volume.dims[axis]);
    spacing[axis] = volume.spacing[axis];
    origin[axis] = volume.origin[axis];
    for (int row = 0; row < 3; ++row) direction[row][axis] = volume.direction[axis][row];
  }
  auto image = LabelImage::New();
  image->SetRegions(region);
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->SetDirection(direction);
  image->Allocate();
  std::uint8_t* labels = image->GetBufferPointer();
  for (std::size_t n = 0; n < volume.voxelCount(); ++n)
    labels[n] = std::uint8_t(labelOf(volume.voxels[n]));
  return image;
}

void writeImage(const LabelImage* image, VolumeFormat format, const std::filesystem::path& file) {
  auto writer = itk::ImageFileWriter<LabelImage>::New();
  writer->SetImageIO(makeImageIO(format));
  writer->SetFileName(file.string());
  writer->SetInput(image);
  writer->SetUseCompression(true);  // labels are long runs: they compress to almost nothing
  writer->Update();
}

}  // namespace

void writeLabelVolume(const std::filesystem::path& path, const Volume& labelsInVolumeBits) {
  const auto format = volumeFormatOf(path);
  const std::string extension = lowercase(path.extension().string());
  if (!format || extension == ".mhd" || extension == ".nhdr")
    throw InputError(path, "unknown label volume format '" + path.extension().string() +
                               "' (use .mha, .nrrd, .nii or .nii.gz)");
  const Volume& volume = labelsInVolumeBits;
  if (volume.voxelCount() == 0 || volume.voxels.size() != volume.voxelCount())
    throw InputError(path, "cannot write an empty or inconsistent label volume");
  try {
    const LabelImage::Pointer image = toLabelImage(volume);
    // ITK's messages name the temporary file; the user's name goes in front of them.
    writeAtomically(path, [&](const std::filesystem::path& temp) { writeImage(image, *format, temp); });
  } catch (const itk::ExceptionObject& error) {
    throw InputError(path, oneLine(error));
  } catch (const std::filesystem::filesystem_error& error) {
    throw InputError(path, error.code().message());
  }
}

}  // namespace angio
