#include "io/volume_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <string>

#include <tbb/parallel_for.h>

#include "io/dicom_series.h"
#include "io/declared_geometry.h"
#include "io/dicom_file_walk.h"
#include "io/dicom_slice_check.h"
#include "io/input_error.h"
#include "io/library_messages.h"
#include "io/segmentation_file.h"
#include "io/volume_conversion.h"
#include "io/volume_formats.h"
#include "io/volume_integrity.h"
#include "io/volume_memory.h"
#include "io/volume_reorientation.h"
#include "io/shown_text.h"
#include "io/voxel_data_layout.h"
#include "io/voxel_slab_reader.h"

namespace angio {

namespace {

// A volume file's voxels exactly as stored (component type and axis order of the file).
struct StoredVolume {
  VolumeGeometry geometry;
  itk::IOComponentEnum componentType = itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE;
  std::unique_ptr<double[]> data;  // raw components; double storage aligns every type
  std::string description;         // "MetaImage float32"
};

void report(const ReadOptions& options, double fraction) {
  if (options.progress) options.progress(fraction);
}

void warn(const ReadOptions& options, const std::string& message) {
  if (options.warn) options.warn(message);
}

std::string dimsText(const std::vector<std::size_t>& dims) {
  std::string text;
  for (std::size_t d = 0; d < dims.size(); ++d) text += (d ? " x " : "") + std::to_string(dims[d]);
  return text;
}

std::string vectorText(glm::dvec3 v, const char* unit) {
  char text[96];
  std::snprintf(text, sizeof text, "%g x %g x %g%s", v.x, v.y, v.z, unit);
  return text;
}

void requireOpenable(const std::filesystem::path& file) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) throw InputError(file, std::string("cannot be opened: ") + std::strerror(errno));
}

// An ImageIO that says it can read `file`, with the header read.
itk::ImageIOBase::Pointer openHeader(const std::filesystem::path& file, std::string& formatLabel) {
  requireOpenable(file);
  itk::ImageIOBase::Pointer io;
  if (const auto format = volumeFormatOf(file)) {
    io = makeImageIO(*format);
    formatLabel = formatName(*format);
    checkDeclaredGeometry(file, *format);  // before ITK parses it (MetaIO can hang on NDims < 0)
    if (!io->CanReadFile(file.c_str()))
      throw InputError(
          file, std::string("is not a valid ") + formatLabel + " file (corrupt or truncated header)");
  } else {
    // Before GDCM sees the file: it takes almost anything for DICOM and trusts its length fields,
    // and its image reader (CanReadFile reads the image) asserts on some tags' values.
    if (!walkDicomFile(file, file))
      throw InputError(file,
                       "unknown volume format (expected .nii, .nii.gz, .nrrd, .nhdr, .mha, "
                       ".mhd or a folder of DICOM slices)");
    checkDicomSlice(file, file, false);
    // Multi-frame images were refused by the checks: the file is one slice. GDCM's image reader is
    // not asked to confirm it, as it would decode compressed pixels in this process
    // (io/slices_in_child.h).
    throw InputError(file, "is a single DICOM slice; open its folder to load the series");
  }
  io->SetFileName(file.string());
  io->ReadImageInformation();
  return io;
}

// Checks the header describes a 3-D scalar volume with sane spacing, and returns where it sits.
VolumeGeometry storedGeometry(const std::filesystem::path& file, const itk::ImageIOBase& io) {
  const unsigned dimensions = io.GetNumberOfDimensions();
  std::vector<std::size_t> dims;
  for (unsigned d = 0; d < dimensions; ++d) dims.push_back(io.GetDimensions(d));
  // Trailing axes of size 1 (a 4-D NIfTI with one time point) do not count.
  std::size_t used = dims.size();
  while (used > 3 && dims[used - 1] == 1) --used;
  std::size_t extent = 0;  // axes with more than one voxel
  for (std::size_t d = 0; d < std::min<std::size_t>(used, 3); ++d) extent += dims[d] > 1;
  if (used > 3)
    throw InputError(file, "is " + std::to_string(used) + "-D (" + dimsText(dims) +
                               " voxels); need a 3-D scalar volume");
  if (used < 3 || extent < 3)
    throw InputError(file, "is " + std::to_string(std::max<std::size_t>(extent, 1)) + "-D (" +
                               dimsText(dims) + " voxels); need a 3-D scalar volume");
  if (io.GetPixelType() == itk::IOPixelEnum::UNKNOWNPIXELTYPE ||
      io.GetComponentType() == itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE)
    throw InputError(file, "has voxels of an unknown type; need integer or floating-point voxels");
  if (io.GetNumberOfComponents() != 1 || io.GetPixelType() != itk::IOPixelEnum::SCALAR)
    throw InputError(file, "has " + std::to_string(io.GetNumberOfComponents()) + "-component " +
                               itk::ImageIOBase::GetPixelTypeAsString(io.GetPixelType()) +
                               " voxels; need a 3-D scalar volume");
  for (int axis = 0; axis < 3; ++axis)
    if (dims[axis] > std::size_t(std::numeric_limits<int>::max()))
      throw InputError(file, "has impossible dimensions (" + dimsText(dims) + ")");
  VolumeGeometry geometry;
  for (int axis = 0; axis < 3; ++axis) {
    geometry.dims[axis] = int(dims[axis]);
    geometry.spacing[axis] = io.GetSpacing(axis);
    geometry.origin[axis] = io.GetOrigin(axis);
    const std::vector<double> column = io.GetDirection(axis);
    for (int row = 0; row < 3; ++row) geometry.direction[axis][row] = column[row];
  }
  const glm::dvec3 s = geometry.spacing;
  if (!(s.x > 0 && s.y > 0 && s.z > 0) || !std::isfinite(s.x + s.y + s.z))
    throw InputError(file, "has zero, negative or invalid voxel spacing (" + vectorText(s, " mm") + ")");
  const glm::dvec3 o = geometry.origin;
  if (!std::isfinite(o.x + o.y + o.z))
    throw InputError(file, "has an invalid origin (" + vectorText(o, " mm") + ")");
  return geometry;
}

void readAllThroughItk(itk::ImageIOBase& io, char* out) {
  itk::ImageIORegion region(io.GetNumberOfDimensions());
  for (unsigned d = 0; d < io.GetNumberOfDimensions(); ++d) {
    region.SetIndex(d, 0);
    region.SetSize(d, io.GetDimensions(d));
  }
  io.SetIORegion(region);
  const LibraryErrorCapture errors;
  io.Read(out);
  // MetaIO says a decompression failed only on std::cerr, and leaves the voxels unset.
  if (const std::string text = errors.text(); !text.empty())
    throw std::invalid_argument("cannot be read: " + readProblemInOurWords(text));
}

// A problem io/ found in the voxel data, naming their file when it is not the header's.
std::invalid_argument voxelDataProblem(const std::filesystem::path& file, const VoxelDataLayout& layout,
                                       const VoxelStreamError& error) {
  const std::string where =
      layout.dataFile == file
          ? ""
          : "its data file " + quotedText(layout.dataFile.filename().string()) + ": ";
  return std::invalid_argument("cannot be read: " + where + error.what());
}

// Reads the voxels as stored into `out`. ITK reads a single-file volume in one call, without
// progress and without a way to stop, so those whose data io/ can decode itself are read here in
// slabs of slices, reporting progress (0.05 to 0.6) between slabs. Every other file, and one whose
// data turns out bad, is read by ITK: its values and its errors stay ITK's.
void readVoxels(const std::filesystem::path& file, itk::ImageIOBase& io,
                const std::optional<VoxelDataLayout>& layout, const VolumeGeometry& geometry, char* out,
                const ReadOptions& options) {
  if (layout) {
    const std::uint64_t slices = std::uint64_t(geometry.dims.z);
    try {
      readVoxelSlabs(*layout, {std::uint64_t(io.GetImageSizeInBytes()) / slices, slices}, out,
                     [&](double fraction) { report(options, 0.05 + 0.55 * fraction); });
      return;
    } catch (const VoxelStreamError& error) {
      // ITK reads the file again and reports its problem in its own words, where it can.
      if (!layout->libraryMayRetry) throw voxelDataProblem(file, *layout, error);
    }
  }
  readAllThroughItk(io, out);
}

// A volume file with its header read and checked, and no voxels read yet.
struct OpenedVolume {
  itk::ImageIOBase::Pointer io;
  VolumeGeometry geometry;
  itk::IOComponentEnum componentType = itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE;
  std::string description;  // "MetaImage float32"
  // Where the voxel bytes lie, when io/ decodes them itself (voxel_data_layout.h).
  std::optional<VoxelDataLayout> layout;

  std::uint64_t storedBytes() const { return std::uint64_t(io->GetImageSizeInBytes()); }
  StoredDataSize storedSize() const { return {storedBytes(), unsigned(io->GetComponentSize())}; }
};

// ITK's and the header checks' errors as InputErrors naming the file.
template <class Read>
auto namingFile(const std::filesystem::path& file, Read read) {
  try {
    return read();
  } catch (const itk::ExceptionObject& error) {
    throw InputError(file, "cannot be read: " + oneLine(error));
  } catch (const std::invalid_argument& error) {
    throw InputError(file, error.what());
  }
}

OpenedVolume openVolume(const std::filesystem::path& file) {
  OpenedVolume opened;
  std::string formatLabel;
  opened.io = openHeader(file, formatLabel);
  opened.geometry = storedGeometry(file, *opened.io);
  opened.componentType = opened.io->GetComponentType();
  opened.description = formatLabel + " " + componentTypeName(opened.componentType);
  withComponentType(opened.componentType, [](auto) { return 0; });  // rejects unusual types
  if (const auto format = volumeFormatOf(file)) {
    requireCompleteData(file, *format, opened.storedSize());
    opened.layout = voxelDataLayout(file, *format, opened.storedSize());
  }
  return opened;
}

// Checks the machine can hold `bytesPerVoxel` per voxel plus `extraBytes`, before allocating.
void requireMemoryFor(const std::filesystem::path& file, const OpenedVolume& opened,
                      double bytesPerVoxel, double extraBytes) {
  const glm::dvec3 dims(opened.geometry.dims);
  requireMemory(file, dims, dims.x * dims.y * dims.z * bytesPerVoxel + extraBytes);
}

// After the memory check (a header's claim the machine cannot hold is the first thing to say):
// teem allocates the whole volume before it finds its data short.
void requireCompleteNrrd(const std::filesystem::path& file, const OpenedVolume& opened) {
  if (volumeFormatOf(file) != VolumeFormat::nrrd) return;
  const NrrdData data = nrrdData(file);
  if (data.place) requireCompleteNrrdData(file, *data.place, opened.storedBytes());
  else if (data.start) requireCompleteNrrdText(file, *data.start, opened.storedSize());
}

// Reads a volume file's header and voxels as stored. `extraBytesPerVoxel` is what the caller will
// allocate on top of the raw data, for the memory check made before anything is allocated.
StoredVolume readStoredVolume(const std::filesystem::path& file, double extraBytesPerVoxel,
                              const ReadOptions& options) {
  return namingFile(file, [&] {
    const OpenedVolume opened = openVolume(file);
    requireMemoryFor(file, opened, extraBytesPerVoxel, double(opened.storedBytes()));
    requireCompleteNrrd(file, opened);
    report(options, 0.05);
    StoredVolume stored;
    stored.geometry = opened.geometry;
    stored.componentType = opened.componentType;
    stored.description = opened.description;
    stored.data = std::make_unique_for_overwrite<double[]>((opened.storedBytes() + sizeof(double) - 1) /
                                                           sizeof(double));
    readVoxels(file, *opened.io, opened.layout, stored.geometry,
               reinterpret_cast<char*>(stored.data.get()), options);
    report(options, 0.6);
    return stored;
  });
}

Reorientation planFor(const std::filesystem::path& file, const VolumeGeometry& geometry) {
  try {
    return planReorientation(geometry.direction);
  } catch (const std::invalid_argument& error) {
    throw InputError(file, std::string("has an invalid direction matrix: ") + error.what());
  }
}

void warnIfOblique(const std::filesystem::path& file, const Reorientation& plan,
                   const ReadOptions& options) {
  if (plan.obliqueDegrees <= 1.0) return;
  char text[64];
  std::snprintf(text, sizeof text, "%.1f", plan.obliqueDegrees);
  warn(options, file.string() + ": oblique volume (an axis is " + text +
                    " degrees off the LPS axes); snapped to the nearest axes for rendering");
}

// A volume placed by `geometry`, holding `voxels` (allocated, zero, if none are given).
Volume volumeOn(const VolumeGeometry& geometry, std::vector<Voxel> voxels = {}) {
  Volume volume;
  volume.dims = geometry.dims;
  volume.spacing = geometry.spacing;
  volume.origin = geometry.origin;
  volume.direction = geometry.direction;
  volume.voxels = std::move(voxels);
  volume.voxels.resize(volume.voxelCount());
  return volume;
}

void warnNonFinite(const std::filesystem::path& file, std::size_t nonFinite,
                   const ReadOptions& options) {
  if (nonFinite > 0)
    warn(options, file.string() + ": " + std::to_string(nonFinite) +
                      " voxels are NaN or infinite; treated as -1024 HU");
}

// The voxels read slab by slab straight into the volume (converted and reoriented per slab): the
// file's stored voxels are never all in memory, so a load peaks at the volume plus one slab.
// Returns the non-finite count, or nothing if the data turned out bad (ITK then reads the file).
std::optional<std::size_t> streamIntoVolume(const std::filesystem::path& file,
                                            const OpenedVolume& opened, const Reorientation& plan,
                                            Volume& volume, const ReadOptions& options) {
  const glm::ivec3 dims = opened.geometry.dims;
  const std::uint64_t sliceBytes = opened.storedBytes() / std::uint64_t(dims.z);
  std::size_t nonFinite = 0;
  try {
    streamVoxelSlabs(
        *opened.layout, {sliceBytes, std::uint64_t(dims.z)},
        [&](const VoxelSlab& slab) {
          nonFinite += withComponentType(opened.componentType, [&](auto type) {
            using T = typename decltype(type)::type;
            return reorientSlab(reinterpret_cast<const T*>(slab.bytes), dims, int(slab.firstSlice),
                                int(slab.sliceCount), plan, volume.voxels.data(), HuToVoxels{});
          });
        },
        [&](double fraction) { report(options, 0.05 + 0.9 * fraction); });
  } catch (const VoxelStreamError& error) {
    if (!opened.layout->libraryMayRetry) throw voxelDataProblem(file, *opened.layout, error);
    return std::nullopt;
  }
  return nonFinite;
}

Volume volumeFromFile(const std::filesystem::path& file, const ReadOptions& options,
                      std::string& description) {
  const OpenedVolume opened = namingFile(file, [&] { return openVolume(file); });
  const Reorientation plan = planFor(file, opened.geometry);
  warnIfOblique(file, plan, options);
  if (opened.layout) {
    // The volume and one slab (1 % of the stored data, see voxel_slab_reader.h).
    requireMemoryFor(file, opened, sizeof(Voxel), 0.02 * double(opened.storedBytes()));
    requireCompleteNrrd(file, opened);
    report(options, 0.05);
    Volume volume = volumeOn(reorientedGeometry(opened.geometry, plan));
    if (const auto nonFinite = streamIntoVolume(file, opened, plan, volume, options)) {
      warnNonFinite(file, *nonFinite, options);
      description = opened.description;
      return volume;
    }
  }
  const StoredVolume stored = readStoredVolume(file, sizeof(Voxel), options);
  Volume volume = volumeOn(reorientedGeometry(stored.geometry, plan));
  const std::size_t nonFinite = withComponentType(stored.componentType, [&](auto type) {
    using T = typename decltype(type)::type;
    return reorientCopy(reinterpret_cast<const T*>(stored.data.get()), stored.geometry.dims, plan,
                        volume.voxels.data(), HuToVoxels{});
  });
  warnNonFinite(file, nonFinite, options);
  description = stored.description;
  return volume;
}

Volume volumeFromDicom(const std::filesystem::path& folder, const ReadOptions& options,
                       std::string& description, StudyInfo& study) {
  const DicomSeries series = scanDicomSeries(folder, options);
  const Reorientation plan = planFor(folder, series.geometry);
  warnIfOblique(folder, plan, options);
  const glm::dvec3 dims(series.geometry.dims);
  requireMemory(folder, dims, dims.x * dims.y * dims.z * sizeof(Voxel));
  // Each slice goes straight to its place in the reoriented volume: no stack of slices. The volume
  // is made at the first slice, after a compressed series' decoder process started: pages it shared
  // with that process would be copied as they are written (twice the memory).
  Volume volume;
  const std::size_t nonFinite = readDicomSlices(
      folder, series,
      [&](int k, const Voxel* slice) {
        if (k == 0) volume = volumeOn(reorientedGeometry(series.geometry, plan));
        reorientSlab(slice, series.geometry.dims, k, 1, plan, volume.voxels.data(), CopyRow{});
      },
      options);
  warnNonFinite(folder, nonFinite, options);
  description = series.description;
  study = series.study;
  return volume;
}

// Same grid up to header rounding: dims exact, spacing and direction to 1e-4, origin to 1% of a voxel.
std::string gridDifference(const VolumeGeometry& labels, const Volume& volume) {
  if (labels.dims != volume.dims)
    return "dims " + vectorText(glm::dvec3(labels.dims), "") + " vs the volume's " +
           vectorText(glm::dvec3(volume.dims), "");
  const glm::dvec3 spacingError = glm::abs(labels.spacing - volume.spacing) / volume.spacing;
  if (glm::any(glm::greaterThan(spacingError, glm::dvec3(1e-4))))
    return "spacing " + vectorText(labels.spacing, " mm") + " vs the volume's " +
           vectorText(volume.spacing, " mm");
  if (glm::length(labels.origin - volume.origin) > 0.01 * voxelUnit(volume))
    return "origin " + vectorText(labels.origin, " mm") + " vs the volume's " +
           vectorText(volume.origin, " mm");
  for (int axis = 0; axis < 3; ++axis)
    if (glm::length(labels.direction[axis] - volume.direction[axis]) > 1e-4)
      return "a different orientation";
  return "";
}

void requireVolumesGrid(const std::filesystem::path& file, const VolumeGeometry& labels,
                        const Volume& volume, bool isSegmentation) {
  const std::string difference = gridDifference(labels, volume);
  if (difference.empty()) return;
  // Slicer 4.11 saved segmentations cropped to their segments by default.
  const std::string slicerHint =
      isSegmentation ? "; in Slicer, set the segmentation's geometry to this CT (Segment Editor, "
                       "Specify geometry) and save it again"
                     : "";
  throw InputError(file, "label volume is not on the volume's grid (" + difference + ")" + slicerHint);
}

// Voxels whose value is no label: an error in a label volume; in a segmentation a warning, as
// Slicer shows no segment for them either.
void reportInvalidLabels(const std::filesystem::path& file, std::size_t invalid, bool isSegmentation,
                         const ReadOptions& options) {
  if (invalid == 0) return;
  if (!isSegmentation)
    throw InputError(file, std::to_string(invalid) + " voxels have label values outside 0..15");
  warn(options, file.string() + ": " + std::to_string(invalid) +
                    " voxels have values that are no segment's label value; read as unlabelled");
}

void addLabels(Volume& volume, const std::filesystem::path& file, const ReadOptions& options) {
  const std::vector<std::uint8_t> labels = readLabels(file, volume, options);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, labels.size(), 1 << 16),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t n = range.begin(); n != range.end(); ++n)
                        volume.voxels[n] = Voxel(densityOf(volume.voxels[n]) | (labels[n] << 12));
                    });
  report(options, 0.95);
}

}  // namespace

std::vector<std::uint8_t> readLabels(const std::filesystem::path& file, const Volume& volume,
                                     const ReadOptions& options) {
  if (!std::filesystem::exists(file)) throw InputError(file, "label volume does not exist");
  if (std::filesystem::is_directory(file))
    throw InputError(
        file, "label volume must be a file (.nii, .nii.gz, .nrrd, .seg.nrrd, .mha), not a folder");
  // A Slicer segmentation's values are its segments' label values (one layer only).
  const std::optional<SegmentationInfo> segmentation = readSegmentationInfo(file);
  ToLabels toLabels;
  if (segmentation) toLabels.valid = segmentLabelValues(file, *segmentation);
  const StoredVolume stored = readStoredVolume(file, 1.0, ReadOptions{});
  const Reorientation plan = planFor(file, stored.geometry);
  requireVolumesGrid(file, reorientedGeometry(stored.geometry, plan), volume, segmentation.has_value());
  std::vector<std::uint8_t> labels(volume.voxelCount());
  const std::size_t invalid = withComponentType(stored.componentType, [&](auto type) {
    using T = typename decltype(type)::type;
    return reorientCopy(reinterpret_cast<const T*>(stored.data.get()), stored.geometry.dims, plan,
                        labels.data(), toLabels);
  });
  reportInvalidLabels(file, invalid, segmentation.has_value(), options);
  return labels;
}

LoadedVolume readVolume(const std::filesystem::path& path, const ReadOptions& options) {
  report(options, 0.0);
  std::error_code error;
  const bool exists = std::filesystem::exists(path, error);
  if (!exists)
    throw InputError(path, error ? "cannot be accessed: " + error.message() : "does not exist");
  LoadedVolume loaded;
  try {
    loaded.volume = std::filesystem::is_directory(path)
                        ? volumeFromDicom(path, options, loaded.description, loaded.study)
                        : volumeFromFile(path, options, loaded.description);
    if (!options.labelPath.empty()) addLabels(loaded.volume, options.labelPath, options);
  } catch (const InputError&) {
    throw;
  } catch (const LoadCancelled&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw InputError(path, "out of memory while loading");
  } catch (const std::exception& error) {  // e.g. a file vanishing mid-read
    throw InputError(path, error.what());
  }
  report(options, 1.0);
  return loaded;
}

}  // namespace angio
