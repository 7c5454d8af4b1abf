#pragma once
// Writing one value per voxel of a Volume to a volume file on the volume's own grid: shared by the
// density, label volume and segmentation writers, so every file they write has exactly the same
// spacing, origin and direction (a label file written beside a CT reads back onto it, and other
// programs place it over the CT), and replaces its target atomically.
#include <filesystem>
#include <functional>

#include <itkImage.h>
#include <itkImageFileWriter.h>
#include <itkMetaDataDictionary.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/volume.h"
#include "io/input_error.h"
#include "io/volume_formats.h"

namespace angio {

template <class T>
using GridImage = itk::Image<T, 3>;

// Throws InputError naming `target` unless it has a volume file extension and `volume` has voxels
// that match its dims; returns the format.
VolumeFormat requireWritableVolume(const Volume& volume, const std::filesystem::path& target);

// Calls write(file) so that `target` appears complete or not at all (see writeAtomically); .mhd and
// .nhdr headers name their data file, so theirs is moved into place before the header. Filesystem
// errors become InputErrors naming `target`.
void writeVolumeFileAtomically(const std::filesystem::path& target,
                               const std::function<void(const std::filesystem::path& file)>& write);

// ITK's error writing `file` as an InputError naming `target` (the name the user gave), with the
// temporary name in ITK's message replaced by it.
InputError volumeWriteError(const itk::ExceptionObject& error, const std::filesystem::path& file,
                            const std::filesystem::path& target);

// An image on `volume`'s grid whose voxel n is value(volume.voxels[n]).
template <class T, class Value>
typename GridImage<T>::Pointer imageOnGrid(const Volume& volume, Value value) {
  typename GridImage<T>::RegionType region;
  typename GridImage<T>::SpacingType spacing;
  typename GridImage<T>::PointType origin;
  typename GridImage<T>::DirectionType direction;
  for (int axis = 0; axis < 3; ++axis) {
    region.SetSize(axis, volume.dims[axis]);
    spacing[axis] = volume.spacing[axis];
    origin[axis] = volume.origin[axis];
    for (int row = 0; row < 3; ++row) direction[row][axis] = volume.direction[axis][row];
  }
  auto image = GridImage<T>::New();
  image->SetRegions(region);
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->SetDirection(direction);
  image->Allocate();
  T* out = image->GetBufferPointer();
  const Voxel* voxels = volume.voxels.data();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, volume.voxelCount(), 1 << 16),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t n = range.begin(); n != range.end(); ++n)
                        out[n] = value(voxels[n]);
                    });
  return image;
}

// Writes value(voxel) of every voxel of `volume` as type T to `target` (format by extension, zlib
// or gzip compressed where the format allows), with `metadata` as header fields where the format
// keeps them (NRRD key/value pairs). Throws InputError naming `target`.
template <class T, class Value>
void writeOnGrid(const Volume& volume, const std::filesystem::path& target, Value value,
                 const itk::MetaDataDictionary& metadata = {}) {
  const VolumeFormat format = requireWritableVolume(volume, target);
  try {
    const typename GridImage<T>::Pointer image = imageOnGrid<T>(volume, value);
    image->SetMetaDataDictionary(metadata);
    writeVolumeFileAtomically(target, [&](const std::filesystem::path& file) {
      auto writer = itk::ImageFileWriter<GridImage<T>>::New();
      writer->SetImageIO(makeImageIO(format));
      writer->SetFileName(file.string());
      writer->SetInput(image);
      writer->SetUseCompression(true);  // NIfTI compresses .nii.gz only
      try {
        writer->Update();
      } catch (const itk::ExceptionObject& error) {
        throw volumeWriteError(error, file, target);
      }
    });
  } catch (const itk::ExceptionObject& error) {  // from building the image (allocation)
    throw InputError(target, oneLine(error));
  }
}

}  // namespace angio
